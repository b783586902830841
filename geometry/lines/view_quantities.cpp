#include "view_quantities.h"

#include "geometry/parallel/lanes.h"
#include "geometry/parallel/parallel.h"

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

namespace {

using lanes::Lanes;

template <typename F>
struct QuantitiesOf {
    F ndotv, contour_ndotv, kr, sc_strength;
};

// One vertex (F = float) or four (F = Lanes): t = eye - position, n the
// normal, cn the contour normal, (d1, d2) the principal directions, C the
// derivative tensor; in the order of operations glm's normalize and dot use.
template <typename F>
QuantitiesOf<F> quantities_of(F tx, F ty, F tz, F nx, F ny, F nz, F cnx, F cny, F cnz, F d1x, F d1y, F d1z, F d2x,
                              F d2y, F d2z, F k1, F k2, F Ca, F Cb, F Cc, F Cd, float fs2) {
    const F inv_len = 1.0f / lanes::root(tx * tx + ty * ty + tz * tz);
    const F vx = tx * inv_len, vy = ty * inv_len, vz = tz * inv_len;
    QuantitiesOf<F> o;
    o.ndotv = nx * vx + ny * vy + nz * vz;
    o.contour_ndotv = cnx * vx + cny * vy + cnz * vz;
    const F u = vx * d1x + vy * d1y + vz * d1z, t = vx * d2x + vy * d2y + vz * d2z;
    const F sin2 = lanes::larger<F>(u * u + t * t, F{} + 1e-12f);
    const F inv_sin = 1.0f / lanes::root(sin2);
    const F wu = u * inv_sin, wt = t * inv_sin;
    const F cwww = wu * wu * (Ca * wu + 3.0f * Cb * wt) + wt * wt * (3.0f * Cc * wu + Cd * wt);
    const F tau = (k2 - k1) * wu * wt;
    const F cot_theta = o.ndotv * inv_sin;
    o.kr = k1 * u * u + k2 * t * t;
    o.sc_strength = (cwww - 2.0f * tau * tau * cot_theta) * fs2;
    return o;
}

}  // namespace

void compute_view_quantities(const Mesh& mesh, const SurfaceFields& fields,
                             const std::vector<glm::vec3>& contour_normals, glm::vec3 eye, float feature_size,
                             const std::vector<uint8_t>& only, size_t begin, size_t end, ViewQuantities& q) {
    const size_t n = mesh.vertex_count();
    const bool all = only.size() != n;
    const std::vector<glm::vec3>& cn = contour_normals.size() == n ? contour_normals : fields.normals;
    const float fs2 = feature_size * feature_size;
    auto needed = [&](size_t i) { return all || only[i] != 0; };
    auto store = [&](size_t i, const auto& o, int j) {
        q.ndotv[i] = lanes::lane(o.ndotv, j), q.contour_ndotv[i] = lanes::lane(o.contour_ndotv, j);
        q.kr[i] = lanes::lane(o.kr, j), q.sc_strength[i] = lanes::lane(o.sc_strength, j);
    };
    const glm::vec3* p = mesh.positions.data();
    const glm::vec3 *nrm = fields.normals.data(), *d1 = fields.d1.data(), *d2 = fields.d2.data();
    const glm::vec4* C = fields.dcurv.data();
    const float *k1 = fields.k1.data(), *k2 = fields.k2.data();
    size_t i = begin;
    for (; i + 4 <= end; i += 4) {  // four at once
        if (!needed(i) && !needed(i + 1) && !needed(i + 2) && !needed(i + 3)) continue;
        using lanes::gather;
        const auto o = quantities_of<Lanes>(
            gather(i, [&](size_t k) { return eye.x - p[k].x; }), gather(i, [&](size_t k) { return eye.y - p[k].y; }),
            gather(i, [&](size_t k) { return eye.z - p[k].z; }), gather(i, [&](size_t k) { return nrm[k].x; }),
            gather(i, [&](size_t k) { return nrm[k].y; }), gather(i, [&](size_t k) { return nrm[k].z; }),
            gather(i, [&](size_t k) { return cn[k].x; }), gather(i, [&](size_t k) { return cn[k].y; }),
            gather(i, [&](size_t k) { return cn[k].z; }), gather(i, [&](size_t k) { return d1[k].x; }),
            gather(i, [&](size_t k) { return d1[k].y; }), gather(i, [&](size_t k) { return d1[k].z; }),
            gather(i, [&](size_t k) { return d2[k].x; }), gather(i, [&](size_t k) { return d2[k].y; }),
            gather(i, [&](size_t k) { return d2[k].z; }), gather(i, [&](size_t k) { return k1[k]; }),
            gather(i, [&](size_t k) { return k2[k]; }), gather(i, [&](size_t k) { return C[k].x; }),
            gather(i, [&](size_t k) { return C[k].y; }), gather(i, [&](size_t k) { return C[k].z; }),
            gather(i, [&](size_t k) { return C[k].w; }), fs2);
        for (int j = 0; j < 4; ++j)
            if (needed(i + size_t(j))) store(i + size_t(j), o, j);
    }
    for (; i < end; ++i) {  // the rest one by one, with the same arithmetic
        if (!needed(i)) continue;
        const glm::vec3 t = eye - p[i];
        store(i,
              quantities_of<float>(t.x, t.y, t.z, nrm[i].x, nrm[i].y, nrm[i].z, cn[i].x, cn[i].y, cn[i].z, d1[i].x,
                                   d1[i].y, d1[i].z, d2[i].x, d2[i].y, d2[i].z, k1[i], k2[i], C[i].x, C[i].y, C[i].z,
                                   C[i].w, fs2),
              0);
    }
}

}  // namespace kappa
