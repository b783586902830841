#include "normals.h"

#include "degenerate.h"
#include "parallel.h"

#include <glm/geometric.hpp>

namespace kappa {

std::vector<glm::vec3> compute_vertex_normals(const Mesh& mesh, const VertexFaces& vf) {
    std::vector<glm::vec3> normals(mesh.vertex_count());
    parallel_for(mesh.vertex_count(), [&](size_t v) {
        glm::dvec3 sum(0.0);
        for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
            const uint32_t c = vf.corners[k];
            const Face& f = mesh.faces[c / 3];
            const int j = int(c % 3);
            const glm::dvec3 p = mesh.positions[f[j]];
            const glm::dvec3 a = glm::dvec3(mesh.positions[f[(j + 1) % 3]]) - p;  // edges leaving v
            const glm::dvec3 b = glm::dvec3(mesh.positions[f[(j + 2) % 3]]) - p;
            if (is_degenerate_triangle(a, b, b - a)) continue;
            // (a x b) has length 2*area; dividing by |a|^2 |b|^2 gives Max's weight.
            sum += glm::cross(a, b) / (glm::dot(a, a) * glm::dot(b, b));
        }
        const double len = glm::length(sum);
        normals[v] = len > 0 && std::isfinite(len) ? glm::vec3(sum / len) : glm::vec3(0.0f);
    });
    return normals;
}

}  // namespace kappa
