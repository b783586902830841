#include "default_view.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
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

// Animals, figures and vehicles are longer than wide and carry their tallest
// parts at their front end: a head, horns, ears, a cab. The surface is
// sampled by face centroids weighted by area (every step-th face). Its long
// horizontal axis is the principal axis of the xz second moments; when it is
// clearly the long one (moment ratio at least 1.5) and the top fifth of the
// model (by height) sits towards one of its ends (its centroid at least 0.2
// of the model's half-length along the axis from the whole's), that end is
// the front and the unit xz direction towards it is returned. Otherwise (a
// cube, a vase, a part with a level top) there is no front: 0.
glm::vec2 front_of_upright_model(const Mesh& mesh, size_t step) {
    struct Sample { glm::dvec2 xz; float y; double w; };
    std::vector<Sample> samples;
    float y_min = INFINITY, y_max = -INFINITY;
    glm::dvec2 centroid(0);
    double total = 0;
    for (size_t f = 0; f < mesh.face_count(); f += step) {
        const Face& t = mesh.faces[f];
        const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        const double w = 0.5 * glm::length(glm::cross(b - a, c - a));
        const glm::vec3 p = (a + b + c) / 3.0f;
        if (!(w > 0) || !std::isfinite(w) || !std::isfinite(p.x + p.y + p.z)) continue;
        samples.push_back({glm::dvec2(p.x, p.z), p.y, w});
        y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
        centroid += w * glm::dvec2(p.x, p.z), total += w;
    }
    if (!(total > 0)) return glm::vec2(0);
    centroid /= total;
    double sxx = 0, sxz = 0, szz = 0;
    for (const Sample& s : samples) {
        const glm::dvec2 d = s.xz - centroid;
        sxx += s.w * d.x * d.x, sxz += s.w * d.x * d.y, szz += s.w * d.y * d.y;
    }
    // Eigen-decomposition of the symmetric 2x2 moment matrix.
    const double mean = 0.5 * (sxx + szz), half_gap = std::hypot(0.5 * (sxx - szz), sxz);
    const double large = mean + half_gap, small = mean - half_gap;
    if (!(large >= 1.5 * small) || !(large > 0)) return glm::vec2(0);
    const double angle = 0.5 * std::atan2(2 * sxz, sxx - szz);
    const glm::dvec2 axis(std::cos(angle), std::sin(angle));

    const float y_top = y_max - 0.2f * (y_max - y_min);
    double top = 0, w_top = 0, half_length = 0;
    for (const Sample& s : samples) {
        const double along = glm::dot(s.xz - centroid, axis);
        half_length = std::max(half_length, std::fabs(along));
        if (s.y >= y_top) top += s.w * along, w_top += s.w;
    }
    if (!(w_top > 0) || !(half_length > 0)) return glm::vec2(0);
    top /= w_top;
    if (!(std::fabs(top) >= 0.2 * half_length)) return glm::vec2(0);
    return glm::vec2(top > 0 ? axis : -axis);
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
    const glm::vec2 front = front_of_upright_model(mesh, step);

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
    // Cosine between a candidate's horizontal direction and the model's front.
    auto towards_front = [&](size_t c) {
        const glm::vec3 d = view_direction(candidates[c]);
        return glm::dot(glm::normalize(glm::vec2(d.x, d.z)), front);
    };
    auto best_of = [&](float min_towards_front) {
        size_t best = 0;
        double best_score = -1;
        for (size_t c = 0; c < candidates.size(); ++c) {
            if (towards_front(c) < min_towards_front) continue;
            const double score = entropy[c] + 0.5 * (max_projected > 0 ? projected[c] / max_projected : 0.0) +
                                 kDetailWeight * (max_detail > 0 ? detail[c] / max_detail : 0.0);
            if (score > best_score + 1e-6) best = c, best_score = score;
        }
        return best;
    };
    size_t best = best_of(-1.0f);
    // Never from behind: a best view more than 120 degrees from the model's
    // front gives way to the best within 50 degrees of it.
    if (front != glm::vec2(0) && towards_front(best) < -0.5f) best = best_of(0.64f);
    return candidates[best];
}

}  // namespace kappa
