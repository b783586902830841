// Writes the C++ source of default_font_atlas() (render/compose/font_atlas.h)
// with the atlas that Debian's libimgui builds, for the browser build, which
// has no libimgui (web/CMakeLists.txt compiles this with the host's compiler
// and runs it):   bake_font_atlas OUT.cpp
#include "render/compose/font_atlas.h"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: bake_font_atlas OUT.cpp\n");
        return 2;
    }
    const kappa::render::FontAtlas atlas = kappa::render::default_font_atlas();
    std::FILE* out = std::fopen(argv[1], "w");
    if (!out) {
        std::perror(argv[1]);
        return 1;
    }
    std::fprintf(out, "// Made by web/tools/bake_font_atlas.cpp from Dear ImGui's built-in font: do not edit.\n"
                      "#include \"render/compose/font_atlas.h\"\n\nnamespace kappa::render {\n\nnamespace {\n\n"
                      "const unsigned char kAlpha[] = {");
    for (size_t i = 0; i < atlas.alpha.size(); ++i)
        std::fprintf(out, "%s%d", i == 0 ? "\n" : i % 32 ? "," : ",\n", atlas.alpha[i]);
    std::fprintf(out, "};\n\nconst FontGlyph kGlyphs[256] = {");
    for (const kappa::render::FontGlyph& g : atlas.glyphs)
        std::fprintf(out, "\n{%.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g},", g.x0, g.y0, g.x1, g.y1, g.u0,
                     g.v0, g.u1, g.v1, g.advance);
    std::fprintf(out, "};\n\n}  // namespace\n\nFontAtlas default_font_atlas() {\n    FontAtlas atlas;\n"
                      "    atlas.width = %d, atlas.height = %d;\n"
                      "    atlas.alpha.assign(kAlpha, kAlpha + sizeof kAlpha);\n"
                      "    for (size_t c = 0; c < 256; ++c) atlas.glyphs[c] = kGlyphs[c];\n"
                      "    return atlas;\n}\n\n}  // namespace kappa::render\n",
                 atlas.width, atlas.height);
    return std::fclose(out) == 0 ? 0 : 1;
}
