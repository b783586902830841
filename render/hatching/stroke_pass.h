// Draws strokes made on the CPU (render/vector/strokes.h; streamline hatching) into
// the line coverage buffer, as the line passes draw theirs: anti-aliased
// quads (shaders/lines/line_quad.glsl, lines_frag.glsl), per-point width (a
// stroke's own width or the default, thinned over its taper) and opacity.
#pragma once

#include "render/camera/frame_params.h"
#include "render/lines/line_raster.h"
#include "render/gl/shader_program.h"
#include "render/vector/strokes.h"

#include <vector>

namespace kappa::render {

// Width of a stroke at arc length s of total length L: `width` thinned to
// 0.2 of it at the ends over `taper` pixels (render/vector/vector_drawing.h uses the same).
float tapered_width(float width, float taper, float s, float total);

// The strokes' segments in window coordinates (y up; strokes come y down),
// on the surface, each with its width (the stroke's own or the default,
// thinned over its taper) and its ends' opacities: what StrokePass draws,
// and what the CPU line raster (render/lines/line_raster.h) draws on software GL.
std::vector<WindowSegment> stroke_window_segments(const std::vector<Stroke>& strokes, float default_width,
                                                  const FrameParams& frame);

class StrokePass {
public:
    StrokePass();   // compiles the shaders (GL context current)
    ~StrokePass();
    StrokePass(const StrokePass&) = delete;
    StrokePass& operator=(const StrokePass&) = delete;
    // Into the bound framebuffer (blending as the line passes: GL_MAX).
    void draw(const std::vector<WindowSegment>& segments, const FrameParams& frame, unsigned surface_depth_texture);

private:
    ShaderProgram program_;
    unsigned vao_ = 0, buffer_ = 0;
};

}  // namespace kappa::render
