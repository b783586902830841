// Surface pass: fills colour and depth with the shaded surface (paper,
// Lambert or toon; colour maps).
#pragma once

#include "render/frame_params.h"
#include "render/mesh_buffers.h"
#include "render/render_settings.h"
#include "render/shader_program.h"

namespace kappa::render {

class SurfaceRenderer {
public:
    SurfaceRenderer();  // compiles the shaders (GL context current)
    // Draws into the bound framebuffer with depth testing.
    void draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings);

private:
    ShaderProgram program_;
    ShaderProgram plain_;  // without a colour map: reads only positions and normals
};

}  // namespace kappa::render
