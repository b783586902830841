// Surface pass: fills colour and depth with the shaded surface (paper,
// Lambert, toon, hemisphere, Gooch; colour maps).
#pragma once

#include "render/back_face_culling.h"
#include "render/frame_params.h"
#include "render/mesh_buffers.h"
#include "render/render_settings.h"
#include "render/shader_program.h"

namespace kappa::render {

// True when the surface pass leaves every pixel the background's colour: a
// white unlit surface (no shading, no colour map) on opaque white. Its
// colour is then not written, and multisampling has no edge to smooth.
bool surface_is_background(const RenderSettings& settings);

class SurfaceRenderer {
public:
    SurfaceRenderer();  // compiles the shaders (GL context current)
    // Draws into the bound framebuffer with depth testing.
    // Back faces are culled where none can be seen (render/back_face_culling.h).
    void draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings);
    void set_back_face_culling(bool on) { back_face_culling_ = on; }  // for tests: off draws every face

private:
    // positions_only: through MeshBuffers::draw_triangle_positions (the paper program).
    void draw_culled(const MeshBuffers& mesh, const FrameParams& frame, const BackFaceCulling& culling,
                     bool positions_only);

    ShaderProgram program_;
    ShaderProgram plain_;  // without a colour map: reads only positions and normals
    ShaderProgram paper_;  // white paper, no colour map: positions only, nothing to interpolate
    bool back_face_culling_ = true;
};

}  // namespace kappa::render
