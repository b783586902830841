// Strokes: per view, the visible parts of the drawn lines as polylines in
// image coordinates, for vector output (SVG, PDF). Lines are extracted on the
// CPU with the GPU passes' tests (geometry/lines/line_extraction.h), chained
// across triangles (geometry/lines/chain.h), and cut where the surface drawn
// in the depth buffer hides them, with the test of shaders/lines/lines_frag.glsl
// (depth at the line's centre, then the farthest of the 3x3 pixels around
// it, plus the line's tolerance), sampled every half pixel along each path:
// exact to the pixel grid of the raster render.
#pragma once

#include "geometry/lines/line_extraction.h"
#include "geometry/mesh/mesh.h"
#include "geometry/surface_fields.h"
#include "render/camera/camera.h"
#include "render/render_settings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace kappa::render {

struct Stroke {
    LineType type = LineType::Contour;
    std::vector<glm::vec2> points;  // pixels: x right, y down, (0, 0) the image's top-left corner
    // Per point, where it lies on the surface, in the mesh's coordinates (the
    // drawing's units: MeshDrawing::units()); empty where not known.
    std::vector<glm::vec3> surface;
    std::vector<float> opacity;     // per point, in [0, 1] (fading)
    std::vector<float> strength;    // per point: the test value fading uses (LineSegment::strength_a); may be empty
    bool hidden = false;            // a hidden part (--hidden-lines): drawn dashed and light
    float width = 0;                // pixels; 0: the drawing's line width
    float taper = -1;               // pixels; < 0: the drawing's taper
};

// What the lines are extracted from: the fields of this view (with --detail,
// the detail-scale fields and the pixel-scale contour normals).
struct StrokeSource {
    const Mesh* mesh = nullptr;
    const SurfaceFields* fields = nullptr;           // with curvature
    const std::vector<glm::vec3>* contour_normals = nullptr;  // may be null or empty
    const std::vector<CreaseEdge>* creases = nullptr;  // may be null
    float feature_size = 1;
};

// The drawn depth of the surface (Renderer::surface_depth) and its size.
struct SurfaceDepth {
    int width = 0, height = 0;
    std::vector<float> depth;  // window depth, bottom row first; 1 = background
};

// Visible strokes of the line types selected in settings (geometry/lines;
// `silhouette` alone keeps the contours with background beside them, as
// shaders/lines/lines_frag.glsl; with --hidden-lines the hidden parts come too,
// marked hidden),
// seen by `camera` over an image of the depth's size. bounds: the mesh's
// bounding sphere (the projection's near and far planes, as the renderer).
std::vector<Stroke> extract_strokes(const StrokeSource& source, const Camera& camera, const BoundingSphere& bounds,
                                    const RenderSettings& settings, const SurfaceDepth& depth);

// Gives the strokes without surface points (hatching, pen-plotter paths)
// theirs: each point's pixel of the drawn depth (or, on the background, the
// nearest surface depth of the 3x3 pixels around it) taken back through the
// camera.
void attach_surface_points(std::vector<Stroke>& strokes, const Camera& camera, const BoundingSphere& bounds,
                           const SurfaceDepth& depth);

}  // namespace kappa::render
