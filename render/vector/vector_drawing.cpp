#include "render/vector/vector_drawing.h"

#include "geometry/io/output_file.h"
#include "render/hatching/stroke_pass.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa::render {

std::optional<VectorFormat> vector_format_for(const std::string& path) {
    const std::string ext = io::lower_extension(path);
    if (ext == "svg") return VectorFormat::Svg;
    if (ext == "pdf") return VectorFormat::Pdf;
    return std::nullopt;
}

std::vector<LineType> layer_order() {
    std::vector<LineType> order{LineType::Hatching};
    for (int t = 0; t < kLineTypeCount; ++t)
        if (LineType(t) != LineType::Hatching) order.push_back(LineType(t));
    return order;
}

int layer_rank(LineType type) { return type == LineType::Hatching ? 0 : int(type) + 1; }

std::vector<StrokePiece> stroke_pieces(const Stroke& stroke, const VectorDrawing& d) {
    const float taper = stroke.taper >= 0 ? stroke.taper : d.taper;
    const float width = stroke.width > 0 ? stroke.width : d.line_width;
    // Resample within `taper` of either end, so that the width can change there.
    std::vector<glm::vec2> points;
    std::vector<float> opacity, along;  // along: arc length from the start
    float total = 0;
    for (size_t i = 0; i + 1 < stroke.points.size(); ++i) total += glm::distance(stroke.points[i], stroke.points[i + 1]);
    float s = 0;
    for (size_t i = 0; i < stroke.points.size(); ++i) {
        if (i > 0) {
            const glm::vec2 a = stroke.points[i - 1], b = stroke.points[i];
            const float len = glm::distance(a, b);
            const bool in_taper = taper > 0 && (s < taper || s + len > total - taper);
            const int steps = in_taper ? std::max(1, int(std::ceil(len))) : 1;
            for (int k = 1; k < steps; ++k) {
                const float t = float(k) / float(steps);
                points.push_back(a + (b - a) * t);
                opacity.push_back(stroke.opacity[i - 1] + (stroke.opacity[i] - stroke.opacity[i - 1]) * t);
                along.push_back(s + len * t);
            }
            s += len;
        }
        points.push_back(stroke.points[i]), opacity.push_back(stroke.opacity[i]), along.push_back(s);
    }
    auto level = [](float x) { return std::round(std::clamp(x, 0.0f, 1.0f) * 16.0f) / 16.0f; };
    std::vector<StrokePiece> pieces;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        // A segment takes the style of its middle.
        const float o = 0.5f * (opacity[i] + opacity[i + 1]);
        const float m = 0.5f * (along[i] + along[i + 1]);
        float w = tapered_width(1.0f, taper, m, total);
        if (d.width_by_strength) w *= o;
        const float piece_opacity = d.width_by_strength ? (o > 0 ? 1.0f : 0.0f) : level(o);
        const float piece_width = width * level(w);
        if (pieces.empty() || pieces.back().opacity != piece_opacity || pieces.back().width != piece_width)
            pieces.push_back({{points[i]}, piece_opacity, piece_width});
        pieces.back().points.push_back(points[i + 1]);
    }
    pieces.erase(std::remove_if(pieces.begin(), pieces.end(),
                                [](const StrokePiece& p) { return p.opacity <= 0 || p.width <= 0; }),
                 pieces.end());
    for (size_t i = 1; i < pieces.size(); ++i)
        if (pieces[i - 1].points.back() == pieces[i].points.front())
            pieces[i - 1].round_end = pieces[i].round_start = false;
    return pieces;
}

PieceCap piece_cap(const StrokePiece& piece, bool at_start) {
    const size_t n = piece.points.size();
    const glm::vec2 end = at_start ? piece.points.front() : piece.points.back();
    glm::vec2 out(1, 0);
    // The direction of the last segment of non-zero length at that end.
    for (size_t k = 1; k < n; ++k) {
        const glm::vec2 d = at_start ? piece.points[k - 1] - piece.points[k] : piece.points[n - k] - piece.points[n - k - 1];
        if (glm::dot(d, d) > 1e-12f) {
            out = glm::normalize(d);
            break;
        }
    }
    const glm::vec2 across(-out.y, out.x);
    const float r = 0.5f * piece.width;
    return {end, out, end + across * r, end - across * r};
}

}  // namespace kappa::render
