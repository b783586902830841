// The line passes with their lines extracted on the CPU (geometry/lines):
// contours, suggestive contours and highlights, Dw kr lines, ridges and
// valleys, parabolic and H = 0 lines, apparent ridges and principal
// highlights, isophotes and topographic lines, per frame, from the
// triangles of the clusters that can hold each kind
// (render/lines/cluster_culling.h), and the open boundary edges, on all worker
// threads, as segments in window
// coordinates. On software GL (llvmpipe) the segments are also drawn on the
// CPU (render/lines/line_raster.h) against the surface's depth read back;
// otherwise each goes through the GL as a quad of two triangles
// (shaders/lines/segment_quads_vert.glsl, no geometry shader). Both draw and
// occlusion-test them as the geometry-shader passes draw theirs
// (tests/test_render_cpu_lines.cpp); on software GL this is much faster
// than a geometry shader on every triangle. Creases and glyphs keep their
// own (cheap) passes. The view-independent kinds' segments are kept between
// frames (render/lines/view_independent_lines.h).
#pragma once

#include "render/camera/frame_params.h"
#include "render/lines/line_raster.h"
#include "geometry/lines/view_quantities.h"
#include "geometry/lines/view_ridges.h"
#include "render/lines/line_prefilter.h"
#include "render/fields/mesh_buffers.h"
#include "render/render_settings.h"
#include "render/gl/shader_program.h"
#include "render/lines/view_independent_lines.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace kappa::render {

// One frame's lines, ready to draw: window-coordinate segments
// (render/lines/line_raster.h), block by block.
struct CpuLines {
    std::vector<std::vector<WindowSegment>> blocks;
    size_t segment_count = 0;
};

class CpuLinePass {
public:
    CpuLinePass();  // compiles the shaders (GL context current)
    ~CpuLinePass();
    CpuLinePass(const CpuLinePass&) = delete;
    CpuLinePass& operator=(const CpuLinePass&) = delete;
    // The lines of a frame, made on the CPU without the GL: may run on any
    // thread while the GL draws the surface (the mesh's CPU copies are not
    // changed during a frame).
    CpuLines prepare(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings) const;
    // Into the bound framebuffer, with the line passes' blending and depth
    // texture bound. coverage_texture: 0, or the bound framebuffer's R8
    // colour texture, still cleared, to rasterise on the CPU into instead,
    // with `strokes` (render/hatching/stroke_pass.h) too (they are ignored with 0),
    // against cpu_depth when given (render/surface/depth_raster.h), else the depth
    // texture read back. Returns where it drew.
    InkArea draw(const CpuLines& lines, const std::vector<WindowSegment>& strokes, const FrameParams& frame,
                 const RenderSettings& settings, GLuint depth_texture, GLuint coverage_texture,
                 const std::vector<float>* cpu_depth = nullptr);

private:
    void ensure_indices(size_t quads);  // the index buffer holds two triangles for at least `quads` quads

    ShaderProgram program_;
    unsigned vao_ = 0, buffer_ = 0, index_buffer_ = 0;
    size_t index_quads_ = 0;
    std::vector<float> depth_;       // read back for the CPU raster, kept between frames
    std::vector<uint8_t> coverage_;
    mutable ViewIndependentLines view_independent_;  // kept between frames by prepare()
    // prepare()'s per-vertex arrays, kept so that a frame need not clear fresh memory.
    struct Scratch {
        std::vector<uint8_t> needed;
        ViewQuantities quantities;
        std::vector<ViewRidgeVertex> ridge_vertices;
        LevelValues levels;
        LinePrefilter prefilter;
    };
    mutable Scratch scratch_;
};

}  // namespace kappa::render
