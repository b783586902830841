#include "voronoi_areas.h"

#include "degenerate.h"
#include "parallel.h"

#include <glm/geometric.hpp>

namespace kappa {

std::vector<glm::vec3> compute_corner_areas(const Mesh& mesh) {
    std::vector<glm::vec3> corner_areas(mesh.face_count());
    parallel_for(mesh.face_count(), [&](size_t i) {
        const Face& f = mesh.faces[i];
        const glm::dvec3 p[3] = {mesh.positions[f[0]], mesh.positions[f[1]], mesh.positions[f[2]]};
        // e[j] is the edge opposite corner j.
        const glm::dvec3 e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};
        if (is_degenerate_triangle(e[0], e[1], e[2])) {
            corner_areas[i] = glm::vec3(0.0f);
            return;
        }
        const double area = 0.5 * glm::length(glm::cross(e[0], e[1]));
        // dot_at[j] = (edge to next corner) . (edge to previous corner), seen from corner j:
        // negative exactly when the angle at j is obtuse.
        const double dot_at[3] = {-glm::dot(e[1], e[2]), -glm::dot(e[2], e[0]), -glm::dot(e[0], e[1])};
        double out[3];
        int obtuse = -1;
        for (int j = 0; j < 3; ++j)
            if (dot_at[j] < 0) obtuse = j;
        if (obtuse >= 0) {
            for (int j = 0; j < 3; ++j) out[j] = (j == obtuse ? 0.5 : 0.25) * area;
        } else {
            // Voronoi area of corner j: (|e_next|^2 cot(angle at next) + |e_prev|^2 cot(angle at prev)) / 8,
            // with cot(angle at k) = dot_at[k] / (2 area).
            for (int j = 0; j < 3; ++j) {
                const int n = (j + 1) % 3, q = (j + 2) % 3;
                // The edge from j to n is opposite q; the edge from j to q is opposite n.
                out[j] = (glm::dot(e[q], e[q]) * dot_at[q] + glm::dot(e[n], e[n]) * dot_at[n]) / (16.0 * area);
            }
        }
        corner_areas[i] = glm::vec3(float(out[0]), float(out[1]), float(out[2]));
    });
    return corner_areas;
}

std::vector<float> compute_point_areas(const VertexFaces& vf, const std::vector<glm::vec3>& corner_areas) {
    const size_t nv = vf.offsets.size() - 1;
    std::vector<float> areas(nv);
    parallel_for(nv, [&](size_t v) {
        double sum = 0;
        for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
            const uint32_t c = vf.corners[k];
            sum += corner_areas[c / 3][c % 3];
        }
        areas[v] = float(sum);
    });
    return areas;
}

}  // namespace kappa
