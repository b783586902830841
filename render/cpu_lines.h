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

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace kappa::render {

// A corner of a segment's quad (shaders/segment_quads_vert.glsl).
struct QuadVertex {
    glm::vec3 end0, end1;
    glm::vec2 alpha;
    float tolerance;
    float kind_corner;  // 4 kind + corner
};

// One frame's lines, ready to draw: the quads' corners, block by block.
struct CpuLines {
    std::vector<std::vector<QuadVertex>> blocks;
    size_t vertex_count = 0;
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
    // Into the bound framebuffer, with the line passes' blending and depth texture bound.
    void draw(const CpuLines& lines, const FrameParams& frame, const RenderSettings& settings);

private:
    void ensure_indices(size_t quads);  // the index buffer holds two triangles for at least `quads` quads

    ShaderProgram program_;
    unsigned vao_ = 0, buffer_ = 0, index_buffer_ = 0;
    size_t index_quads_ = 0;
};

}  // namespace kappa::render
