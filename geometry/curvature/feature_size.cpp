#include "feature_size.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace kappa {

namespace {

float median(std::vector<float>& values) {
    if (values.empty()) return 0.0f;
    auto mid = values.begin() + values.size() / 2;
    std::nth_element(values.begin(), mid, values.end());
    return *mid;
}

}  // namespace

float feature_size(const Mesh& mesh, const SurfaceFields& fields) {
    if (mesh.positions.empty()) return 0.0f;
    // Bounding sphere: centre of the bounding box, radius to the farthest vertex.
    glm::vec3 lo = mesh.positions[0], hi = lo;
    for (const auto& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 centre = 0.5f * (lo + hi);
    float radius = 0;
    for (const auto& p : mesh.positions) radius = std::max(radius, glm::length(p - centre));

    std::vector<float> edges;
    edges.reserve(mesh.faces.size());
    for (const Face& f : mesh.faces) {  // one edge per face is a fair sample of all edges
        const float len = glm::length(mesh.positions[f[1]] - mesh.positions[f[0]]);
        if (len > 0) edges.push_back(len);
    }
    const float lower = std::min(median(edges), radius);

    std::vector<float> radii;
    radii.reserve(fields.size());
    for (size_t i = 0; i < fields.size(); ++i) {
        if (fields.flags[i]) continue;
        const float kmax = std::max(std::fabs(fields.k1[i]), std::fabs(fields.k2[i]));
        radii.push_back(kmax > 0 ? 1.0f / kmax : radius);
    }
    if (radii.empty()) return radius;
    return std::clamp(median(radii), lower, radius);
}

}  // namespace kappa
