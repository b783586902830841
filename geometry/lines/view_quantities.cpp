#include "view_quantities.h"

#include "geometry/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

ViewQuantities compute_view_quantities(const Mesh& mesh, const SurfaceFields& fields,
                                       const std::vector<glm::vec3>& contour_normals, glm::vec3 eye,
                                       float feature_size, const std::vector<uint8_t>& only) {
    ViewQuantities q;
    compute_view_quantities(mesh, fields, contour_normals, eye, feature_size, only, q);
    return q;
}

void compute_view_quantities(const Mesh& mesh, const SurfaceFields& fields,
                             const std::vector<glm::vec3>& contour_normals, glm::vec3 eye, float feature_size,
                             const std::vector<uint8_t>& only, ViewQuantities& q) {
    const size_t n = mesh.vertex_count();
    q.ndotv.resize(n), q.contour_ndotv.resize(n), q.kr.resize(n), q.sc_strength.resize(n);
    parallel_for_ranges(n, [&](size_t begin, size_t end) {
        compute_view_quantities(mesh, fields, contour_normals, eye, feature_size, only, begin, end, q);
    });
}

void compute_view_quantities(const Mesh& mesh, const SurfaceFields& fields,
                             const std::vector<glm::vec3>& contour_normals, glm::vec3 eye, float feature_size,
                             const std::vector<uint8_t>& only, size_t begin, size_t end, ViewQuantities& q) {
    const size_t n = mesh.vertex_count();
    const bool all = only.size() != n;
    const bool own_contour_normals = contour_normals.size() == n;
    const float fs2 = feature_size * feature_size;
    for (size_t i = begin; i < end; ++i) {
        if (!all && !only[i]) continue;
        const glm::vec3 v = glm::normalize(eye - mesh.positions[i]);
        const glm::vec3& nrm = fields.normals[i];
        const float k1 = fields.k1[i], k2 = fields.k2[i];
        const glm::vec4& C = fields.dcurv[i];
        const float ndotv = glm::dot(nrm, v);
        const float u = glm::dot(v, fields.d1[i]), t = glm::dot(v, fields.d2[i]);
        const float sin2 = std::max(u * u + t * t, 1e-12f);
        const float inv_sin = 1.0f / std::sqrt(sin2);
        const float wu = u * inv_sin, wt = t * inv_sin;
        const float cwww = wu * wu * (C.x * wu + 3.0f * C.y * wt) + wt * wt * (3.0f * C.z * wu + C.w * wt);
        const float tau = (k2 - k1) * wu * wt;
        const float cot_theta = ndotv * inv_sin;
        q.ndotv[i] = ndotv;
        q.contour_ndotv[i] = own_contour_normals ? glm::dot(contour_normals[i], v) : ndotv;
        q.kr[i] = k1 * u * u + k2 * t * t;
        q.sc_strength[i] = (cwww - 2.0f * tau * tau * cot_theta) * fs2;
    }
}

}  // namespace kappa
