// Full-screen and overlay passes: compositing lines over the surface into
// the target framebuffer, and the colour bar.
#pragma once

#include "render/render_settings.h"
#include "render/shader_program.h"
#include "render/text_labels.h"

namespace kappa::render {

class Compositor {
public:
    Compositor();
    ~Compositor();
    // Draws surface * (1 - lines) + line_color * lines into the bound
    // framebuffer (same size as the textures).
    void draw(GLuint surface_texture, GLuint lines_texture, glm::vec3 line_color);
    // The same, with the surface already in the bound framebuffer: blends the
    // lines over it (cheaper: no surface read, nothing written without a line).
    void draw_over(GLuint lines_texture, glm::vec3 line_color);

private:
    ShaderProgram program_;
    ShaderProgram over_;
    GLuint vao_ = 0;  // empty: the vertex shader makes the triangle
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
