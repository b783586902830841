// Hatching drawn on the GPU (--hatch-style shader; the viewer while the view
// moves): no readback and no tracing on the CPU.
//   1. Field pass: the visible surface drawn into two targets, both
//      principal directions projected into the window as doubled angles
//      times their reliability, and the tone's darkness where the surface
//      faces the eye (shaders/hatching/hatch_vectors_*.glsl).
//   2. Stroke pass: one full-screen pass that draws the phasor-noise strokes
//      of shaders/hatching/shader_hatching.glsl along those directions, as
//      coverage into the line buffer (GL_MAX), where the compositor inks
//      them like every line.
// Evaluated once a pixel, not per fragment of the surface: on a fine mesh a
// GPU shades every small triangle in blocks of 2 x 2 pixels, and the strokes
// would be computed several times over.
#pragma once

#include "render/camera/frame_params.h"
#include "render/fields/mesh_buffers.h"
#include "render/gl/gl.h"
#include "render/gl/shader_program.h"
#include "render/render_settings.h"

namespace kappa::render {

class ShaderHatchingPass {
public:
    ShaderHatchingPass();  // compiles the shaders (GL context current)
    ~ShaderHatchingPass();
    ShaderHatchingPass(const ShaderHatchingPass&) = delete;
    ShaderHatchingPass& operator=(const ShaderHatchingPass&) = delete;

    // Draws settings.hatching's strokes into `coverage_framebuffer` (one
    // channel, as the line passes; blended with GL_MAX) and leaves it bound.
    void draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings,
              GLuint coverage_framebuffer);
    void set_back_face_culling(bool on) { back_face_culling_ = on; }  // for tests: off draws every face

private:
    void ensure_targets(int width, int height);
    ShaderProgram field_, strokes_;
    GLuint fbo_ = 0, directions_ = 0, darkness_ = 0, depth_ = 0, vao_ = 0;
    int width_ = 0, height_ = 0;
    bool back_face_culling_ = true;
};

}  // namespace kappa::render
