// Line coverage rasterised on the CPU, for software GL. llvmpipe shades a
// thin quad in blocks of 4x4 pixels, most of them outside the line, and
// that was the largest part of the CPU line pass's drawing time; here each
// row of a segment's quad visits only the pixels inside it.
//
// Per pixel this is shaders/lines/lines_frag.glsl for a segment of the CPU line
// pass (shaders/lines/segment_quads_vert.glsl) or a stroke (strokes_geom.glsl: on
// the surface, drawn only where the pixel shows the surface): box-filtered
// coverage of a line of constant width, visibility decided at the closest
// point q of the centre line against the surface depth at q (then the
// farthest of the 3x3 pixels around it, with the segment's tolerance), the
// exterior-silhouette test, and --hidden-lines dashes. The result is
// max-blended into an 8-bit coverage image as the GL's GL_MAX blending into
// an R8 target would (float to unorm8 by rounding).
//
// Rows are cut into bands drawn in parallel, each band writing only its own
// rows: the image is the same for any thread count.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace kappa::render {

struct WindowSegment {
    glm::vec3 a, b;          // window coordinates: pixels from the bottom-left corner, depth in [0, 1]
    glm::vec2 alpha;         // opacity at a and at b
    float tolerance = 0;     // model units a line may lie behind the surface and still be seen
    bool exterior_only = false;  // drawn only where one side is background (the exterior silhouette)
    bool on_surface = false;     // a stroke: drawn only over the surface, never dashed
    float width = 0;             // pixels; 0: LineRasterParams::line_width
};

struct LineRasterParams {
    int width = 0, height = 0;  // pixels
    float line_width = 1;       // pixels, of the segments whose own width is 0
    glm::vec2 depth_params{0};  // (P[2][2], P[3][2]) of the projection: window depth -> camera distance
    bool hidden_lines = false;  // hidden parts dashed (6 px every 10) at 35% ink instead of not drawn
};

// depth: width x height window depths, the bottom row first (glReadPixels'
// order), 1 where there is no surface. coverage: width x height bytes in the
// same order, max-blended with what it holds (resized and cleared when its
// size is wrong).
void rasterize_lines(const std::vector<WindowSegment>& segments, const std::vector<float>& depth,
                     const LineRasterParams& params, std::vector<uint8_t>& coverage);

// Where the line passes left ink in their coverage image: nowhere, anywhere
// (a GL pass drew), or only inside `rects` (every line drawn on the CPU).
struct InkArea {
    bool anywhere = false;
    std::vector<glm::ivec4> rects;  // x, y, width, height: pixels, the bottom row first
    bool empty() const { return !anywhere && rects.empty(); }
};

// Rectangles (x, y, width, height; pixels, the bottom row first) that hold
// every non-zero pixel of a width x height coverage image: the inked cells
// of a grid of `cell` x `cell` pixels, each run of inked cells along a row
// of the grid merged into one rectangle. Where to blend the lines over the
// surface, instead of the whole image.
std::vector<glm::ivec4> inked_rectangles(const std::vector<uint8_t>& coverage, int width, int height, int cell = 16);

}  // namespace kappa::render
