// Mixed Voronoi areas (Meyer, Desbrun, Schroeder & Barr 2002, sec. 3.3,
// Fig. 4): each triangle's area is split among its corners by the Voronoi
// regions of its vertices; in an obtuse triangle the obtuse corner gets half
// the area and the other two a quarter each.
#pragma once

#include "vertex_faces.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace kappa {

// Corner areas of one non-degenerate triangle with edges e[j] opposite
// corner j (e[0] = p2 - p1, e[1] = p0 - p2, e[2] = p1 - p0) and area `area`.
inline glm::dvec3 mixed_voronoi_corner_areas(const glm::dvec3 (&e)[3], double area) {
    // dot_at[j] = (edge to next corner) . (edge to previous corner) seen from corner j:
    // negative exactly when the angle at j is obtuse; cot(angle at j) = dot_at[j] / (2 area).
    const double dot_at[3] = {-glm::dot(e[1], e[2]), -glm::dot(e[2], e[0]), -glm::dot(e[0], e[1])};
    for (int j = 0; j < 3; ++j)
        if (dot_at[j] < 0) {
            glm::dvec3 out(0.25 * area);
            out[j] = 0.5 * area;
            return out;
        }
    // Voronoi area of corner j: (|PQ|^2 cot R + |PR|^2 cot Q) / 8 with Q, R the other corners; the
    // edge from j to corner n is e[q] and the edge from j to corner q is e[n].
    glm::dvec3 out;
    for (int j = 0; j < 3; ++j) {
        const int n = (j + 1) % 3, q = (j + 2) % 3;
        out[j] = (glm::dot(e[q], e[q]) * dot_at[q] + glm::dot(e[n], e[n]) * dot_at[n]) / (16.0 * area);
    }
    return out;
}

// Per vertex, the sum of its corner areas.
std::vector<float> compute_point_areas(const VertexFaces& vf, const std::vector<glm::vec3>& corner_areas);

}  // namespace kappa
