// default_font_atlas (font_atlas.h) from Dear ImGui's own atlas builder.
#include "render/compose/font_atlas.h"

#include <imgui.h>

namespace kappa::render {

FontAtlas default_font_atlas() {
    ImFontAtlas atlas;
    ImFont* font = atlas.AddFontDefault();
    unsigned char* pixels = nullptr;
    FontAtlas out;
    atlas.GetTexDataAsAlpha8(&pixels, &out.width, &out.height);
    out.alpha.assign(pixels, pixels + size_t(out.width) * size_t(out.height));
    for (size_t c = 0; c < out.glyphs.size(); ++c)
        if (const ImFontGlyph* g = font->FindGlyph(ImWchar(c)))  // the fallback glyph where the font has none
            out.glyphs[c] = {g->X0, g->Y0, g->X1, g->Y1, g->U0, g->V0, g->U1, g->V1, g->AdvanceX};
    return out;
}

}  // namespace kappa::render
