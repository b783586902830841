// When a triangle is too thin to carry any geometric information.
#pragma once

#include "geometry/parallel/double_lanes.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

// A triangle is degenerate when twice its area is below 1e-7 times its
// longest squared edge (its smallest angle is below ~1e-7 rad), i.e. it is
// collinear to float precision, or when it is not finite. Such faces get
// zero weight everywhere (normals, areas, curvature) instead of NaN.
// The test the other way round, per lane (double_lanes.h): set where the
// triangle with edges e0, e1, e2 is usable.
template <typename D>
KAPPA_LANES_INLINE lanes::Mask<D> nondegenerate_triangle(const lanes::Vec3<D>& e0, const lanes::Vec3<D>& e1,
                                                         const lanes::Vec3<D>& e2) {
    using namespace lanes;
    const Vec3<D> twice_area_normal = cross(e0, e1);
    const D twice_area = root(dot(twice_area_normal, twice_area_normal));
    const D longest2 = larger(larger(dot(e0, e0), dot(e1, e1)), dot(e2, e2));  // std::max's order
    return (twice_area > 1e-7 * longest2) & (twice_area - twice_area == 0.0);   // the latter: finite
}
inline bool is_degenerate_triangle(const glm::dvec3& e0, const glm::dvec3& e1, const glm::dvec3& e2) {
    using V = lanes::Vec3<double>;
    return !nondegenerate_triangle<double>(V{e0.x, e0.y, e0.z}, V{e1.x, e1.y, e1.z}, V{e2.x, e2.y, e2.z});
}

}  // namespace kappa
