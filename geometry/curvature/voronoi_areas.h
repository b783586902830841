// Mixed Voronoi areas (Meyer, Desbrun, Schroeder & Barr 2002, sec. 3.3,
// Fig. 4): each triangle's area is split among its corners by the Voronoi
// regions of its vertices; in an obtuse triangle the obtuse corner gets half
// the area and the other two a quarter each.
#pragma once

#include "geometry/parallel/double_lanes.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace kappa {

// Corner areas of one non-degenerate triangle with edges e[j] opposite
// corner j (e[0] = p2 - p1, e[1] = p0 - p2, e[2] = p1 - p0) and area `area`.
template <typename D>
KAPPA_LANES_INLINE lanes::Vec3<D> mixed_voronoi_corner_areas(const lanes::Vec3<D> (&e)[3], D area) {
    using namespace lanes;
    // dot_at[j] = (edge to next corner) . (edge to previous corner) seen from corner j:
    // negative exactly when the angle at j is obtuse; cot(angle at j) = dot_at[j] / (2 area).
    const D dot_at[3] = {-dot(e[1], e[2]), -dot(e[2], e[0]), -dot(e[0], e[1])};
    // Obtuse at j (the first such corner): half the area there, a quarter at the others.
    const Mask<D> obtuse[3] = {Mask<D>(dot_at[0] < 0.0), Mask<D>((dot_at[1] < 0.0) & (dot_at[0] >= 0.0)),
                               Mask<D>((dot_at[2] < 0.0) & (dot_at[0] >= 0.0) & (dot_at[1] >= 0.0))};
    const Mask<D> any_obtuse = obtuse[0] | obtuse[1] | obtuse[2];
    // Else the Voronoi area of corner j: (|PQ|^2 cot R + |PR|^2 cot Q) / 8 with Q, R the other
    // corners; the edge from j to corner n is e[q] and the edge from j to corner q is e[n].
    D out[3];
    for (int j = 0; j < 3; ++j) {
        const int n = (j + 1) % 3, q = (j + 2) % 3;
        const D voronoi = (dot(e[q], e[q]) * dot_at[q] + dot(e[n], e[n]) * dot_at[n]) / (16.0 * area);
        out[j] = select<D>(any_obtuse, select<D>(obtuse[j], 0.5 * area, 0.25 * area), voronoi);
    }
    return {out[0], out[1], out[2]};
}
inline glm::dvec3 mixed_voronoi_corner_areas(const glm::dvec3 (&e)[3], double area) {
    const lanes::Vec3<double> v[3] = {{e[0].x, e[0].y, e[0].z}, {e[1].x, e[1].y, e[1].z}, {e[2].x, e[2].y, e[2].z}};
    const lanes::Vec3<double> out = mixed_voronoi_corner_areas<double>(v, area);
    return {out.x, out.y, out.z};
}

}  // namespace kappa
