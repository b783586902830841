#include "face_geometry.h"

#include "degenerate.h"
#include "io/prefault.h"
#include "parallel.h"
#include "voronoi_areas.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace kappa {

FaceGeometry compute_face_geometry(const Mesh& mesh) {
    const size_t nf = mesh.face_count();
    FaceGeometry g;
    for (auto* v : {&g.area_normals, &g.inv_edge_len2, &g.corner_areas}) {
        io::reserve_prefaulted(*v, nf);  // fresh memory: mapped by all threads at once
        v->resize(nf);
    }
    parallel_for(nf, [&](size_t i) {
        const Face& f = mesh.faces[i];
        const glm::dvec3 p[3] = {mesh.positions[f[0]], mesh.positions[f[1]], mesh.positions[f[2]]};
        const glm::dvec3 e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};
        if (is_degenerate_triangle(e[0], e[1], e[2])) {
            g.area_normals[i] = g.inv_edge_len2[i] = g.corner_areas[i] = glm::vec3(0.0f);
            return;
        }
        const glm::dvec3 n = glm::cross(e[2], -e[1]);  // (p1 - p0) x (p2 - p0)
        const glm::vec3 il2(1.0 / glm::dot(e[0], e[0]), 1.0 / glm::dot(e[1], e[1]), 1.0 / glm::dot(e[2], e[2]));
        if (!std::isfinite(il2.x + il2.y + il2.z)) {  // edges too short for float (< ~1e-19)
            g.area_normals[i] = g.inv_edge_len2[i] = g.corner_areas[i] = glm::vec3(0.0f);
            return;
        }
        g.area_normals[i] = glm::vec3(n);
        g.inv_edge_len2[i] = il2;
        g.corner_areas[i] = glm::vec3(mixed_voronoi_corner_areas(e, 0.5 * glm::length(n)));
    });
    return g;
}

}  // namespace kappa
