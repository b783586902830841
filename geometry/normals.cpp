#include "normals.h"

#include "parallel.h"
#include "prefetch.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace kappa {

std::vector<glm::vec3> compute_vertex_normals(const VertexFaces& vf, const FaceGeometry& faces) {
    const size_t nv = vf.offsets.size() - 1;
    std::vector<glm::vec3> normals(nv);
    parallel_for(nv, [&](size_t v) {
        glm::dvec3 sum(0.0);
        for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
            const uint32_t c = vf.corners[k], f = c / 3, j = c % 3;
            prefetch_face_ahead(vf, k, faces.area_normals.data());
            prefetch_face_ahead(vf, k, faces.inv_edge_len2.data());
            // The two edges at corner j are those opposite the other two corners.
            const glm::vec3& il2 = faces.inv_edge_len2[f];
            sum += glm::dvec3(faces.area_normals[f]) * (double(il2[(j + 1) % 3]) * il2[(j + 2) % 3]);
        }
        const double len = glm::length(sum);
        normals[v] = len > 0 && std::isfinite(len) ? glm::vec3(sum / len) : glm::vec3(0.0f);
    });
    return normals;
}

}  // namespace kappa
