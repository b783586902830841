// The contour pass with its lines extracted on the CPU: occluding contours,
// suggestive contours and highlights, Dw kr lines (geometry/lines), per
// frame, from the triangles of the clusters that can hold them
// (render/cluster_culling.h), on all worker threads; only the segments go
// through the GL (shaders/segments_*.glsl, drawn and occlusion-tested as
// the GPU pass's). On software renderers (llvmpipe) this is much faster
// than running a geometry shader on every triangle, and draws the same
// lines (tests/test_render_cpu_isolines.cpp).
#pragma once

#include "render/frame_params.h"
#include "render/mesh_buffers.h"
#include "render/render_settings.h"
#include "render/shader_program.h"

namespace kappa::render {

class CpuIsolinePass {
public:
    CpuIsolinePass();  // compiles the shaders (GL context current)
    ~CpuIsolinePass();
    CpuIsolinePass(const CpuIsolinePass&) = delete;
    CpuIsolinePass& operator=(const CpuIsolinePass&) = delete;
    // Into the bound framebuffer, with the line passes' blending and depth texture bound.
    void draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings);

private:
    ShaderProgram program_;
    unsigned vao_ = 0, buffer_ = 0;
};

}  // namespace kappa::render
