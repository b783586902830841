// The line passes with their lines extracted on the CPU (geometry/lines):
// contours, suggestive contours and highlights, Dw kr lines, ridges and
// valleys, parabolic and H = 0 lines, apparent ridges and principal
// highlights, isophotes and topographic lines, per frame, from the
// triangles of the clusters that can hold each kind
// (render/cluster_culling.h), on all worker threads. Only the segments go
// through the GL, each as a quad of two triangles
// (shaders/segment_quads_vert.glsl, with no geometry shader), drawn and
// occlusion-tested as the geometry-shader passes draw theirs. On software renderers (llvmpipe)
// this is much faster than a geometry shader on every triangle, and draws
// the same lines (tests/test_render_cpu_lines.cpp). Creases, boundaries and
// glyphs keep their own (cheap) passes.
#pragma once

#include "render/frame_params.h"
#include "render/mesh_buffers.h"
#include "render/render_settings.h"
#include "render/shader_program.h"

namespace kappa::render {

class CpuLinePass {
public:
    CpuLinePass();  // compiles the shaders (GL context current)
    ~CpuLinePass();
    CpuLinePass(const CpuLinePass&) = delete;
    CpuLinePass& operator=(const CpuLinePass&) = delete;
    // Into the bound framebuffer, with the line passes' blending and depth texture bound.
    void draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings);

private:
    void ensure_indices(size_t quads);  // the index buffer holds two triangles for at least `quads` quads

    ShaderProgram program_;
    unsigned vao_ = 0, buffer_ = 0, index_buffer_ = 0;
    size_t index_quads_ = 0;
};

}  // namespace kappa::render
