// When a triangle is too thin to carry any geometric information.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

// A triangle is degenerate when twice its area is below 1e-7 times its
// longest squared edge (its smallest angle is below ~1e-7 rad), i.e. it is
// collinear to float precision, or when it is not finite. Such faces get
// zero weight everywhere (normals, areas, curvature) instead of NaN.
inline bool is_degenerate_triangle(const glm::dvec3& e0, const glm::dvec3& e1, const glm::dvec3& e2) {
    const double twice_area = glm::length(glm::cross(e0, e1));
    const double longest2 = std::max({glm::dot(e0, e0), glm::dot(e1, e1), glm::dot(e2, e2)});
    return !(twice_area > 1e-7 * longest2) || !std::isfinite(twice_area);
}

}  // namespace kappa
