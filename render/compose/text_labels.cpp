#include "render/compose/text_labels.h"

#include "render/compose/font_atlas.h"

#include <cmath>
#include <vector>

namespace kappa::render {

struct TextLabels::Fonts {
    FontAtlas atlas = default_font_atlas();
};

TextLabels::TextLabels()
    : program_({{GL_VERTEX_SHADER, {"overlay/text_vert.glsl"}}, {GL_FRAGMENT_SHADER, {"overlay/text_frag.glsl"}}}),
      fonts_(new Fonts) {
    const FontAtlas& atlas = fonts_->atlas;
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas.width, atlas.height, 0, GL_RED, GL_UNSIGNED_BYTE, atlas.alpha.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // a pixel font: whole pixels
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &buffer_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), reinterpret_cast<const void*>(2 * sizeof(float)));
    glBindVertexArray(0);
}

TextLabels::~TextLabels() {
    glDeleteBuffers(1, &buffer_);
    glDeleteVertexArrays(1, &vao_);
    glDeleteTextures(1, &texture_);
    delete fonts_;
}

float TextLabels::width(const std::string& text, float scale) const {
    float w = 0;
    for (char c : text) w += fonts_->atlas.glyphs[static_cast<unsigned char>(c)].advance;
    return w * scale;
}

void TextLabels::draw(const std::string& text, glm::vec2 at, float scale, glm::vec3 color, int width, int height) {
    // Glyph boxes are given from the top of the line, y down: flip to y up.
    std::vector<float> v;
    // Whole pixels: the glyphs' one-pixel strokes (the minus) must cover pixel centres.
    float x = std::round(at.x);
    const float top = std::round(at.y + 0.5f * kHeight * scale);
    for (char c : text) {
        const FontGlyph& g = fonts_->atlas.glyphs[static_cast<unsigned char>(c)];
        const float x0 = x + g.x0 * scale, x1 = x + g.x1 * scale;
        const float y0 = top - g.y0 * scale, y1 = top - g.y1 * scale;
        const float quad[6][4] = {{x0, y0, g.u0, g.v0}, {x1, y0, g.u1, g.v0}, {x1, y1, g.u1, g.v1},
                                  {x0, y0, g.u0, g.v0}, {x1, y1, g.u1, g.v1}, {x0, y1, g.u0, g.v1}};
        for (const auto& corner : quad) v.insert(v.end(), corner, corner + 4);
        x += g.advance * scale;
    }
    if (v.empty()) return;
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    program_.use();
    program_.set("u_viewport", glm::vec2(float(width), float(height)));
    program_.set("u_color", color);
    program_.set("u_atlas", 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(float)), v.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(v.size() / 4));
    glBindVertexArray(0);
    glDisable(GL_BLEND);
}

}  // namespace kappa::render
