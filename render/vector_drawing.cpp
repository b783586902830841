#include "render/vector_drawing.h"

#include "geometry/io/output_file.h"

#include <algorithm>
#include <cmath>

namespace kappa::render {

std::optional<VectorFormat> vector_format_for(const std::string& path) {
    const std::string ext = io::lower_extension(path);
    if (ext == "svg") return VectorFormat::Svg;
    if (ext == "pdf") return VectorFormat::Pdf;
    return std::nullopt;
}

std::vector<StrokePiece> pieces_of_equal_opacity(const Stroke& stroke) {
    std::vector<StrokePiece> pieces;
    auto level = [](float opacity) { return std::round(std::clamp(opacity, 0.0f, 1.0f) * 16.0f) / 16.0f; };
    for (size_t i = 0; i + 1 < stroke.points.size(); ++i) {
        // A segment takes the opacity of its middle.
        const float o = level(0.5f * (stroke.opacity[i] + stroke.opacity[i + 1]));
        if (pieces.empty() || pieces.back().opacity != o) {
            pieces.push_back({{stroke.points[i]}, o});
        }
        pieces.back().points.push_back(stroke.points[i + 1]);
    }
    pieces.erase(std::remove_if(pieces.begin(), pieces.end(), [](const StrokePiece& p) { return p.opacity <= 0; }),
                 pieces.end());
    return pieces;
}

}  // namespace kappa::render
