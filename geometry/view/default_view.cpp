#include "default_view.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace kappa {

namespace {

constexpr int kBins = 64;
constexpr size_t kMaxSampledFaces = 200000;
constexpr double kDetailWeight = 1.0;

// Fibonacci sphere: kBins nearly uniform directions.
std::array<glm::vec3, kBins> bin_directions() {
    std::array<glm::vec3, kBins> dirs;
    const float golden = float(M_PI) * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < kBins; ++i) {
        const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(kBins);
        const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
        dirs[size_t(i)] = {r * std::cos(golden * float(i)), y, r * std::sin(golden * float(i))};
    }
    return dirs;
}

}  // namespace

glm::vec3 view_direction(ViewAngles a) {
    const float az = glm::radians(a.azimuth), el = glm::radians(a.elevation);
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

ViewAngles choose_default_view(const Mesh& mesh) {
    // Vertex normals (area-weighted face normals), for how much each face bends.
    std::vector<glm::vec3> vertex_normal(mesh.vertex_count(), glm::vec3(0.0f));
    for (const Face& t : mesh.faces) {
        const glm::vec3 c = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                       mesh.positions[t[2]] - mesh.positions[t[0]]);
        if (!std::isfinite(c.x + c.y + c.z)) continue;
        for (int k = 0; k < 3; ++k) vertex_normal[t[k]] += c;
    }
    // Area-weighted face normals (sampled), their orientation bins and their
    // bending: how far the vertex normals turn from the face's, per unit of
    // length (a curvature, so detail draws the eye: faces, hands, ears).
    const auto dirs = bin_directions();
    const size_t step = std::max<size_t>(1, (mesh.face_count() + kMaxSampledFaces - 1) / kMaxSampledFaces);
    std::vector<glm::vec3> area_normals;
    std::vector<uint8_t> bin;
    std::vector<float> bending;
    for (size_t f = 0; f < mesh.face_count(); f += step) {
        const Face& t = mesh.faces[f];
        const glm::vec3 c = 0.5f * glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                              mesh.positions[t[2]] - mesh.positions[t[0]]);
        const float a = glm::length(c);
        if (!(a > 0) || !std::isfinite(a)) continue;
        int best = 0;
        for (int b = 1; b < kBins; ++b)
            if (glm::dot(c, dirs[size_t(b)]) > glm::dot(c, dirs[size_t(best)])) best = b;
        area_normals.push_back(c);
        bin.push_back(uint8_t(best));
        float turn = 0, perimeter = 0;
        for (int k = 0; k < 3; ++k) {
            const float ln = glm::length(vertex_normal[t[k]]);
            if (ln > 0) turn += glm::length(vertex_normal[t[k]] / ln - c / a);
            perimeter += glm::length(mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]);
        }
        bending.push_back(perimeter > 0 ? 3.0f * turn / perimeter : 0.0f);
    }

    // Candidates in tie-breaking order.
    std::vector<ViewAngles> candidates;
    for (int k = 30; k < 180; k += 15)
        for (int sign : {1, -1})
            if (k % 90 != 0)
                for (float el : {20.0f, 35.0f}) candidates.push_back({float(sign * k), el});
    for (float el : {20.0f, 35.0f}) {
        candidates.push_back({15, el});
        candidates.push_back({-15, el});
        candidates.push_back({165, el});
        candidates.push_back({-165, el});
    }
    if (area_normals.empty()) return {30, 20};

    std::vector<double> entropy(candidates.size()), projected(candidates.size()), detail(candidates.size());
    double max_projected = 0, max_detail = 0;
    for (size_t c = 0; c < candidates.size(); ++c) {
        const glm::vec3 d = view_direction(candidates[c]);
        std::array<double, kBins> weight{};
        double total = 0, bent = 0;
        for (size_t f = 0; f < area_normals.size(); ++f) {
            const double w = glm::dot(area_normals[f], d);
            if (w > 0) weight[bin[f]] += w, total += w, bent += w * bending[f];
        }
        detail[c] = bent;
        max_detail = std::max(max_detail, bent);
        double h = 0;
        for (double w : weight)
            if (w > 0) h -= (w / total) * std::log(w / total);
        entropy[c] = total > 0 ? h / std::log(double(kBins)) : 0.0;
        projected[c] = total;
        max_projected = std::max(max_projected, total);
    }
    size_t best = 0;
    double best_score = -1;
    for (size_t c = 0; c < candidates.size(); ++c) {
        const double score = entropy[c] + 0.5 * (max_projected > 0 ? projected[c] / max_projected : 0.0) +
                             kDetailWeight * (max_detail > 0 ? detail[c] / max_detail : 0.0);
        if (score > best_score + 1e-6) best = c, best_score = score;
    }
    return candidates[best];
}

}  // namespace kappa
