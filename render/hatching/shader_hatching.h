// Hatching drawn on the GPU (--hatch-style shader; the viewer while the view
// moves): no readback and no tracing on the CPU, and no other pass over the
// mesh.
//   1. The surface pass writes, beside its colour, the visible surface's
//      principal directions projected into the window as doubled angles
//      times their reliability, and the tone's darkness where it faces the
//      eye, into two more targets (attach / detach around it; resolved when
//      the surface is multisampled).
//   2. One full-screen pass draws the phasor-noise strokes of
//      shaders/hatching/shader_hatching.glsl along those directions as
//      coverage into the line buffer (GL_MAX), where the compositor inks
//      them like every line.
// Evaluated once a pixel, not per fragment of the surface: on a fine mesh a
// GPU shades every small triangle in blocks of 2 x 2 pixels, and the strokes
// would be computed several times over. (Software GL draws them in the
// surface pass itself: SurfaceHatching::Strokes.)
#pragma once

#include "render/camera/frame_params.h"
#include "render/gl/gl.h"
#include "render/gl/shader_program.h"
#include "render/render_settings.h"

namespace kappa::render {

// The uniforms of shaders/hatching/shader_hatching.glsl (which families,
// spacing, stroke width) for the program in use: the stroke pass's here, or
// the surface pass's when it draws the strokes itself.
void set_hatching_uniforms(ShaderProgram& program, const RenderSettings& settings);

class ShaderHatchingPass {
public:
    ShaderHatchingPass();  // compiles the shaders (GL context current)
    ~ShaderHatchingPass();
    ShaderHatchingPass(const ShaderHatchingPass&) = delete;
    ShaderHatchingPass& operator=(const ShaderHatchingPass&) = delete;

    // Before the surface pass (SurfaceHatching::Targets): the targets are
    // colour attachments 1 and 2 of `surface_framebuffer` (width x height,
    // `samples` as its own; attached once and kept), cleared, and draw
    // buffers 1 and 2 beside its own 0.
    void attach(GLuint surface_framebuffer, int width, int height, int samples);
    // After it: resolved when multisampled, and the framebuffer draws into
    // attachment 0 alone again.
    void detach(GLuint surface_framebuffer);
    // The strokes into `coverage_framebuffer` (one channel, as the line
    // passes; blended with GL_MAX), left bound.
    void draw(const FrameParams& frame, const RenderSettings& settings, GLuint coverage_framebuffer);

private:
    ShaderProgram strokes_;
    GLuint directions_ = 0, darkness_ = 0;  // single-sample textures the stroke pass reads
    GLuint ms_directions_ = 0, ms_darkness_ = 0, resolve_fbo_ = 0;  // renderbuffers when multisampled
    GLuint vao_ = 0;
    int width_ = 0, height_ = 0, samples_ = 0;
};

}  // namespace kappa::render
