#include "feature_size.h"

#include "geometry/mesh/position_bounds.h"
#include "geometry/parallel/select_value.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

namespace kappa {

float feature_size(const Mesh& mesh, const SurfaceFields& fields) {
    if (mesh.positions.empty()) return 0.0f;
    // Bounding sphere: centre of the bounding box, radius to the farthest vertex
    // (maxima: the same whatever the order, so in parallel).
    const size_t nv = mesh.positions.size();
    const PositionBounds box = position_bounds(mesh.positions);
    const glm::vec3 lo = box.lo, hi = box.hi;
    std::mutex merge;
    const glm::vec3 centre = 0.5f * (lo + hi);
    float radius = 0;
    parallel_for_ranges(nv, [&](size_t first, size_t last) {
        float r = 0;
        for (size_t i = first; i < last; ++i) r = std::max(r, glm::length(mesh.positions[i] - centre));
        std::lock_guard<std::mutex> lock(merge);
        radius = std::max(radius, r);
    }, 65536);

    // Medians (the element at m / 2 of m, as nth_element), of edge lengths and
    // of radii of curvature: geometry/parallel/select_value.h.
    const auto middle = [](size_t m) { return m / 2; };
    // One edge per face is a fair sample of all edges; zero lengths left out.
    const float edge = select_nonnegative(mesh.faces.size(), [&](size_t f) {
        const Face& face = mesh.faces[f];
        const float len = glm::length(mesh.positions[face[1]] - mesh.positions[face[0]]);
        return len > 0 ? len : -1.0f;
    }, middle);
    const float lower = std::min(std::isnan(edge) ? 0.0f : edge, radius);

    const float median_radius = select_nonnegative(fields.size(), [&](size_t i) {
        if (fields.flags[i]) return -1.0f;  // unreliable or isolated: left out
        const float kmax = std::max(std::fabs(fields.k1[i]), std::fabs(fields.k2[i]));
        return kmax > 0 ? 1.0f / kmax : radius;
    }, middle);
    if (std::isnan(median_radius)) return radius;
    return std::clamp(median_radius, lower, radius);
}

}  // namespace kappa
