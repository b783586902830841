// PDF output of a VectorDrawing (render/vector/vector_drawing.h), through cairo.
#include "render/vector/vector_drawing.h"

#include <cmath>
#include <cairo-pdf.h>
#include <cairo.h>

#include <stdexcept>

namespace kappa::render {

void write_pdf(const std::string& path, const VectorDrawing& d) {
    cairo_surface_t* surface = cairo_pdf_surface_create(path.c_str(), d.width, d.height);
    cairo_t* cr = cairo_create(surface);
    if (d.background.a > 0) {
        cairo_set_source_rgba(cr, d.background.r, d.background.g, d.background.b, d.background.a);
        cairo_paint(cr);
    }
    if (d.underlay) {
        // cairo's ARGB32 is premultiplied, native-endian 0xAARRGGBB.
        cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, d.width, d.height);
        cairo_surface_flush(image);
        unsigned char* data = cairo_image_surface_get_data(image);
        const int stride = cairo_image_surface_get_stride(image);
        for (int y = 0; y < d.height; ++y)
            for (int x = 0; x < d.width; ++x) {
                const Rgba p = d.underlay->at(x, y);
                auto pre = [&](uint8_t c) { return uint32_t((unsigned(c) * p.a + 127) / 255); };
                const uint32_t argb = uint32_t(p.a) << 24 | pre(p.r) << 16 | pre(p.g) << 8 | pre(p.b);
                *reinterpret_cast<uint32_t*>(data + size_t(y) * size_t(stride) + size_t(x) * 4) = argb;
            }
        cairo_surface_mark_dirty(image);
        cairo_set_source_surface(cr, image, 0, 0);
        cairo_paint(cr);
        cairo_surface_destroy(image);
    }
    cairo_set_line_width(cr, d.line_width);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    // Hidden parts first (dashed 6 on 4, at 35% ink), then the line types in layer order.
    auto draw = [&](const Stroke& s) {
        for (const StrokePiece& piece : stroke_pieces(s, d)) {
            cairo_set_line_width(cr, piece.width);
            cairo_set_source_rgba(cr, d.line_color.r, d.line_color.g, d.line_color.b,
                                  piece.opacity * (s.hidden ? 0.35 : 1.0));
            cairo_move_to(cr, piece.points[0].x, piece.points[0].y);
            for (size_t i = 1; i < piece.points.size(); ++i) cairo_line_to(cr, piece.points[i].x, piece.points[i].y);
            if (piece.round_start && piece.round_end) {
                cairo_stroke(cr);
                continue;
            }
            // Butt ends where it joins its neighbours; its own round ends as half discs.
            cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
            cairo_stroke(cr);
            cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
            for (const bool at_start : {true, false}) {
                if (!(at_start ? piece.round_start : piece.round_end)) continue;
                const PieceCap c = piece_cap(piece, at_start);
                const double out = std::atan2(double(c.outward.y), double(c.outward.x));
                cairo_new_path(cr);
                cairo_arc(cr, c.centre.x, c.centre.y, 0.5 * piece.width, out - M_PI / 2, out + M_PI / 2);
                cairo_close_path(cr);
                cairo_fill(cr);
            }
        }
    };
    const double dash[] = {6.0, 4.0};
    cairo_set_dash(cr, dash, 2, 0);
    for (const Stroke& s : d.strokes)
        if (s.hidden) draw(s);
    cairo_set_dash(cr, nullptr, 0, 0);
    for (const LineType type : layer_order())
        for (const Stroke& s : d.strokes)
            if (s.type == type && !s.hidden) draw(s);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    const cairo_status_t status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error(path + ": cannot write PDF (" + cairo_status_to_string(status) + ")");
}

}  // namespace kappa::render
