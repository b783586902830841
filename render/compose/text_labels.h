// Short text (numbers, axis names) drawn into the current framebuffer, for
// the colour bar's labels. The glyphs come from Dear ImGui's built-in font
// (ProggyClean, 13 px, font_atlas.h), which the viewer already ships: its
// font atlas is put once into a one-channel texture, and each character is a
// textured quad. Works headless (no ImGui context or window needed).
#pragma once

#include "render/gl/shader_program.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace kappa::render {

class TextLabels {
public:
    TextLabels();  // needs a current GL context
    ~TextLabels();
    TextLabels(const TextLabels&) = delete;
    TextLabels& operator=(const TextLabels&) = delete;

    // Width in pixels of `text` at `scale` (1 = 13 px high).
    float width(const std::string& text, float scale) const;
    // Draws `text` with its left end at x and its vertical middle at y
    // (window pixels, origin bottom left) into a width x height viewport.
    void draw(const std::string& text, glm::vec2 at, float scale, glm::vec3 color, int width, int height);

    static constexpr float kHeight = 13.0f;  // pixels at scale 1

private:
    ShaderProgram program_;
    GLuint vao_ = 0, buffer_ = 0, texture_ = 0;
    struct Fonts;
    Fonts* fonts_ = nullptr;
};

}  // namespace kappa::render
