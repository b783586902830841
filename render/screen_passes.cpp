#include "render/screen_passes.h"

#include <algorithm>

namespace kappa::render {

Compositor::Compositor()
    : program_({{GL_VERTEX_SHADER, {"fullscreen_vert.glsl"}}, {GL_FRAGMENT_SHADER, {"compose_frag.glsl"}}}) {
    glGenVertexArrays(1, &vao_);
}

Compositor::~Compositor() { glDeleteVertexArrays(1, &vao_); }

void Compositor::draw(GLuint surface_texture, GLuint lines_texture, glm::vec3 line_color) {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    program_.use();
    program_.set("u_surface", 0);
    program_.set("u_lines", 1);
    program_.set("u_line_color", line_color);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, surface_texture);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, lines_texture);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

ColorBar::ColorBar()
    : program_({{GL_VERTEX_SHADER, {"colorbar_vert.glsl"}},
                {GL_FRAGMENT_SHADER, {"colormap.glsl", "colorbar_frag.glsl"}}}) {
    glGenVertexArrays(1, &vao_);
}

ColorBar::~ColorBar() { glDeleteVertexArrays(1, &vao_); }

void ColorBar::draw(ColorMap map, float range, int width, int height) {
    if (map == ColorMap::None) return;
    const float margin = std::max(4.0f, 0.03f * float(std::min(width, height)));
    float w = std::max(8.0f, 0.035f * float(width)), h = 0.5f * float(height);
    if (map == ColorMap::Principal) w = h = std::max(16.0f, 0.22f * float(std::min(width, height)));
    const glm::vec4 rect(float(width) - margin - w, (float(height) - h) * 0.5f, w, h);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    program_.use();
    program_.set("u_rect", rect);
    program_.set("u_viewport", glm::vec2(float(width), float(height)));
    program_.set("u_colormap", int(map));
    program_.set("u_map_range", range);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

}  // namespace kappa::render
