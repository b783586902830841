#include "render/compose/screen_passes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace kappa::render {

Compositor::Compositor()
    : program_({{GL_VERTEX_SHADER, {"common/fullscreen_vert.glsl"}}, {GL_FRAGMENT_SHADER, {"lines/lines_over_frag.glsl"}}}),
      rects_({{GL_VERTEX_SHADER, {"lines/screen_rects_vert.glsl"}}, {GL_FRAGMENT_SHADER, {"lines/lines_over_frag.glsl"}}}) {
    glGenVertexArrays(1, &vao_);
    glGenVertexArrays(1, &rects_vao_);
    glGenBuffers(1, &rects_buffer_);
    glBindVertexArray(rects_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, rects_buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), nullptr);
    glBindVertexArray(0);
}

Compositor::~Compositor() {
    glDeleteVertexArrays(1, &vao_);
    glDeleteVertexArrays(1, &rects_vao_);
    glDeleteBuffers(1, &rects_buffer_);
}

void Compositor::draw_over(GLuint lines_texture, glm::vec3 line_color, const InkArea& ink) {
    if (ink.empty()) return;
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    ShaderProgram& p = ink.anywhere ? program_ : rects_;
    p.use();
    p.set("u_lines", 0);
    p.set("u_line_color", line_color);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, lines_texture);
    if (ink.anywhere) {
        glBindVertexArray(vao_);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    } else {
        // Two triangles a rectangle, in normalised device coordinates.
        GLint viewport[4];
        glGetIntegerv(GL_VIEWPORT, viewport);
        const glm::vec2 to_ndc(2.0f / float(viewport[2]), 2.0f / float(viewport[3]));
        std::vector<glm::vec2> corners;
        corners.reserve(6 * ink.rects.size());
        for (const glm::ivec4& r : ink.rects) {
            const glm::vec2 lo = glm::vec2(r.x, r.y) * to_ndc - 1.0f, hi = glm::vec2(r.x + r.z, r.y + r.w) * to_ndc - 1.0f;
            for (const glm::vec2 c : {lo, glm::vec2(hi.x, lo.y), hi, lo, hi, glm::vec2(lo.x, hi.y)}) corners.push_back(c);
        }
        glBindVertexArray(rects_vao_);
        glBindBuffer(GL_ARRAY_BUFFER, rects_buffer_);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(corners.size() * sizeof(glm::vec2)), corners.data(), GL_STREAM_DRAW);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(corners.size()));
    }
    glBindVertexArray(0);
    glDisable(GL_BLEND);
}

ColorBar::ColorBar()
    : program_({{GL_VERTEX_SHADER, {"overlay/colorbar_vert.glsl"}},
                {GL_FRAGMENT_SHADER, {"common/colormap.glsl", "overlay/colorbar_frag.glsl"}}}) {
    glGenVertexArrays(1, &vao_);
}

ColorBar::~ColorBar() { glDeleteVertexArrays(1, &vao_); }

void ColorBar::draw(ColorMap map, float range, int width, int height, glm::vec4 background) {
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

    // Labels: values at the ends (and zero), right-aligned left of the bar.
    const float scale = std::max(1.0f, std::floor(float(std::min(width, height)) / 500.0f));
    const float luminance = 0.3f * background.r + 0.59f * background.g + 0.11f * background.b;
    const glm::vec3 ink = background.a > 0.5f && luminance < 0.5f ? glm::vec3(0.9f) : glm::vec3(0.1f);
    auto number = [](float v, bool plus) {
        char text[32];
        std::snprintf(text, sizeof text, plus && v > 0 ? "+%.3g" : "%.3g", double(v));
        return std::string(text);
    };
    const float gap = 4.0f * scale;
    auto left_of_bar = [&](const std::string& text, float y) {
        labels_.draw(text, {rect.x - gap - labels_.width(text, scale), y}, scale, ink, width, height);
    };
    const float bottom = rect.y, top = rect.y + rect.w, middle = rect.y + 0.5f * rect.w;
    if (map == ColorMap::DCurv) {
        left_of_bar(number(range, false), top);
        left_of_bar("0", bottom);
    } else if (map == ColorMap::Principal) {  // k1 along x, k2 along y, both over [-range, range]
        left_of_bar(number(range, true), top);
        left_of_bar("k2", middle);
        left_of_bar(number(-range, false), bottom);
        const float below = bottom - gap - 0.5f * TextLabels::kHeight * scale;
        labels_.draw(number(-range, false), {rect.x, below}, scale, ink, width, height);
        const std::string right = number(range, true);
        labels_.draw(right, {rect.x + rect.z - labels_.width(right, scale), below}, scale, ink, width, height);
        labels_.draw("k1", {rect.x + 0.5f * (rect.z - labels_.width("k1", scale)), below}, scale, ink, width, height);
    } else {
        left_of_bar(number(range, true), top);
        left_of_bar("0", middle);
        left_of_bar(number(-range, false), bottom);
    }
}

}  // namespace kappa::render
