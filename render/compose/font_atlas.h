// The bitmap font of the colour bar's labels (text_labels.h): Dear ImGui's
// built-in font (ProggyClean, 13 px), which the viewer already ships, as a
// one-channel atlas and the glyphs of character codes 0 to 255.
// On the desktop it is built from Debian's libimgui (imgui_font_atlas.cpp);
// the browser build, which has no libimgui, bakes the same atlas into its
// sources when it is built (web/tools/bake_font_atlas.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace kappa::render {

struct FontGlyph {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // box from the pen, pixels, y down from the line's top
    float u0 = 0, v0 = 0, u1 = 0, v1 = 0;  // in the atlas
    float advance = 0;                     // pixels to the next pen position
};

struct FontAtlas {
    int width = 0, height = 0;
    std::vector<uint8_t> alpha;         // width x height coverage, rows from the top
    std::array<FontGlyph, 256> glyphs;  // by character code; the font's fallback glyph where it has none
};

FontAtlas default_font_atlas();

}  // namespace kappa::render
