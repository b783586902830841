// SVG output of a VectorDrawing (render/vector/vector_drawing.h).
#include "render/vector/vector_drawing.h"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace kappa::render {

namespace {

struct FileCloser {
    void operator()(FILE* f) const { std::fclose(f); }
};

std::string base64(const std::vector<uint8_t>& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t n = uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0) |
                           (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0);
        out += table[n >> 18 & 63];
        out += table[n >> 12 & 63];
        out += i + 1 < bytes.size() ? table[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? table[n & 63] : '=';
    }
    return out;
}

std::vector<uint8_t> encode_png(const Image& image) {
    std::vector<uint8_t> png;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* out = static_cast<std::vector<uint8_t>*>(context);
            out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
        },
        &png, image.width, image.height, 4, image.pixels.data(), image.width * 4);
    return png;
}

std::string hex_color(glm::vec3 c) {
    char buf[8];
    auto byte = [](float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return buf;
}

}  // namespace

void write_svg(const std::string& path, const VectorDrawing& d) {
    std::unique_ptr<FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
    if (!file) throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
    FILE* f = file.get();
    std::fprintf(f,
                 "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\"\n"
                 "     xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"\n"
                 "     version=\"1.1\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n",
                 d.width, d.height, d.width, d.height);
    if (d.background.a > 0)
        std::fprintf(f, "<rect width=\"%d\" height=\"%d\" fill=\"%s\" fill-opacity=\"%g\"/>\n", d.width, d.height,
                     hex_color(glm::vec3(d.background)).c_str(), double(d.background.a));
    if (d.underlay)
        std::fprintf(f,
                     "<g inkscape:groupmode=\"layer\" id=\"surface\" inkscape:label=\"surface\">\n"
                     "<image width=\"%d\" height=\"%d\" xlink:href=\"data:image/png;base64,%s\"/>\n</g>\n",
                     d.width, d.height, base64(encode_png(*d.underlay)).c_str());
    // Hidden parts first (under everything drawn), then a layer per line type.
    auto write_paths = [&](const Stroke& s) {
        for (const StrokePiece& piece : stroke_pieces(s, d)) {
            std::fputs("<path d=\"M", f);
            for (size_t i = 0; i < piece.points.size(); ++i)
                std::fprintf(f, "%s%.2f %.2f", i == 1 ? " L" : " ", double(piece.points[i].x), double(piece.points[i].y));
            if (piece.opacity < 1) std::fprintf(f, "\" stroke-opacity=\"%.4g", double(piece.opacity));
            if (piece.width != d.line_width) std::fprintf(f, "\" stroke-width=\"%.4g", double(piece.width));
            if (piece.round_start && piece.round_end) {
                std::fputs("\"/>\n", f);
                continue;
            }
            // Butt ends where it joins its neighbours; its own round ends as half discs.
            std::fputs("\" stroke-linecap=\"butt\"/>\n", f);
            for (const bool at_start : {true, false}) {
                if (!(at_start ? piece.round_start : piece.round_end)) continue;
                const PieceCap c = piece_cap(piece, at_start);
                const float r = 0.5f * piece.width;
                std::fprintf(f, "<path d=\"M%.2f %.2f A%.4g %.4g 0 0 1 %.2f %.2f Z\" stroke=\"none\" fill=\"%s\"",
                             double(c.right.x), double(c.right.y), double(r), double(r), double(c.left.x),
                             double(c.left.y), hex_color(d.line_color).c_str());
                if (piece.opacity < 1) std::fprintf(f, " fill-opacity=\"%.4g\"", double(piece.opacity));
                std::fputs("/>\n", f);
            }
        }
    };
    auto open_layer = [&](const char* name, const char* extra) {
        std::fprintf(f,
                     "<g inkscape:groupmode=\"layer\" id=\"%s\" inkscape:label=\"%s\" fill=\"none\" stroke=\"%s\" "
                     "stroke-width=\"%g\" stroke-linecap=\"round\" stroke-linejoin=\"round\"%s>\n",
                     name, name, hex_color(d.line_color).c_str(), double(d.line_width), extra);
    };
    bool opened = false;
    for (const Stroke& s : d.strokes) {
        if (!s.hidden) continue;
        if (!opened) open_layer("hidden", " stroke-dasharray=\"6 4\" opacity=\"0.35\""), opened = true;
        write_paths(s);
    }
    if (opened) std::fputs("</g>\n", f);
    for (const LineType type : layer_order()) {
        opened = false;
        for (const Stroke& s : d.strokes) {
            if (s.type != type || s.hidden) continue;
            if (!opened) open_layer(line_type_name(type), ""), opened = true;
            write_paths(s);
        }
        if (opened) std::fputs("</g>\n", f);
    }
    std::fputs("</svg>\n", f);
    if (std::fflush(f) != 0 || std::ferror(f)) throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
}

}  // namespace kappa::render
