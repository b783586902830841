// Full-screen and overlay passes: the lines over the surface, and the
// colour bar.
#pragma once

#include "render/lines/line_raster.h"
#include "render/render_settings.h"
#include "render/gl/shader_program.h"
#include "render/compose/text_labels.h"

namespace kappa::render {

class Compositor {
public:
    Compositor();
    ~Compositor();
    // Blends the lines over the surface in the bound framebuffer (same size
    // as the texture): surface * (1 - lines) + line_color * lines, where
    // `ink` says lines may be (a software rasteriser shades every pixel it
    // is given, even those it then discards).
    void draw_over(GLuint lines_texture, glm::vec3 line_color, const InkArea& ink);

private:
    ShaderProgram program_;
    ShaderProgram rects_;  // the same over rectangles
    GLuint vao_ = 0;       // empty: the vertex shader makes the triangle
    GLuint rects_vao_ = 0, rects_buffer_ = 0;
};

class ColorBar {
public:
    ColorBar();
    ~ColorBar();
    // A vertical bar at the right edge of a width x height viewport (a
    // square for the two-dimensional principal map), with the values of its
    // ends (and of zero for signed maps) written beside it, dark on a light
    // background and light on a dark one.
    void draw(ColorMap map, float range, int width, int height, glm::vec4 background);

private:
    ShaderProgram program_;
    GLuint vao_ = 0;
    TextLabels labels_;
};

}  // namespace kappa::render
