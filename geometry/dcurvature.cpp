#include "dcurvature.h"

#include "ldlt.h"
#include "parallel.h"

#include <glm/geometric.hpp>

namespace kappa {

namespace {

// Normal equations of the fit above, with the kuv equation counted twice
// (kuv appears twice in the tensor): a 4x4 SPD system in (a, b, c, d).
bool fit_face_dcurv(const glm::dvec3 (&e)[3], const Tensor2 (&fcurv)[3], const glm::dvec3& t, const glm::dvec3& b,
                    glm::vec4& out) {
    double m[4] = {}, uu = 0, uv = 0, vv = 0;
    for (int j = 0; j < 3; ++j) {
        const int prev = (j + 2) % 3, next = (j + 1) % 3;
        const double u = glm::dot(e[j], t), v = glm::dot(e[j], b);
        const double dku = double(fcurv[prev].ku) - fcurv[next].ku;
        const double dkuv = double(fcurv[prev].kuv) - fcurv[next].kuv;
        const double dkv = double(fcurv[prev].kv) - fcurv[next].kv;
        uu += u * u;
        uv += u * v;
        vv += v * v;
        m[0] += u * dku;
        m[1] += v * dku + 2.0 * u * dkuv;
        m[2] += 2.0 * v * dkuv + u * dkv;
        m[3] += v * dkv;
    }
    // [[uu, uv, 0, 0], [uv, 2uu + vv, 2uv, 0], [0, 2uv, uu + 2vv, uv], [0, 0, uv, vv]] (a, b, c, d)^T = m
    const double diag[4] = {uu, 2 * uu + vv, uu + 2 * vv, vv}, off[3] = {uv, 2 * uv, uv};
    double x[4];
    if (!ldlt_solve_tridiagonal<4>(diag, off, m, x)) return false;
    out = glm::vec4(float(x[0]), float(x[1]), float(x[2]), float(x[3]));
    return true;
}

}  // namespace

namespace {

// A vertex's tangent frame (u, v) for normal n, rotated into face f's plane, in (t, b) coordinates.
inline FrameChange vertex_in_face(const FaceFits& fits, size_t f, const glm::vec3& u, const glm::vec3& v,
                           const glm::vec3& n) {
    const glm::vec3 &t = fits.t[f], &b = fits.b[f];
    return frame_change(t, b, glm::cross(t, b), u, v, n);
}

}  // namespace

std::vector<glm::vec4> compute_dcurv(const Mesh& mesh, const VertexFaces& vf, FaceFits fits,
                                     const std::vector<glm::vec3>& corner_areas, const std::vector<glm::vec3>& normals,
                                     VertexTensors tensors, const std::vector<glm::vec3>& d1) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    std::vector<Tensor2>().swap(fits.tensor);
    std::vector<glm::vec4> face_dcurv(nf);
    std::vector<uint8_t>& face_ok = fits.ok;  // cleared where the C fit fails too
    parallel_for(nf, [&](size_t i) {
        if (!face_ok[i]) return;
        const Face& f = mesh.faces[i];
        const glm::dvec3 p[3] = {mesh.positions[f[0]], mesh.positions[f[1]], mesh.positions[f[2]]};
        const glm::dvec3 e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};
        // Vertex tensors in the face frame: the inverse (transposed) rotation.
        Tensor2 fcurv[3];
        for (int j = 0; j < 3; ++j) {
            glm::vec3 u, v;
            tangent_frame(normals[f[j]], u, v);
            fcurv[j] = transform_tensor(vertex_in_face(fits, i, u, v, normals[f[j]]).transposed(), tensors.tensor[f[j]]);
        }
        face_ok[i] = fit_face_dcurv(e, fcurv, fits.t[i], fits.b[i], face_dcurv[i]);
    });
    std::vector<Tensor2>().swap(tensors.tensor);

    std::vector<glm::vec4> dcurv(nv, glm::vec4(0.0f));
    parallel_for(nv, [&](size_t vi) {
        glm::vec3 u, v;
        tangent_frame(normals[vi], u, v);
        // Average in the vertex frame (u, v), then turn the (linear) result into the principal frame.
        glm::vec4 sum(0.0f);
        float wsum = 0;
        for (uint32_t k = vf.begin(vi); k < vf.end(vi); ++k) {
            const uint32_t corner = vf.corners[k], fi = corner / 3;
            if (!face_ok[fi]) continue;
            const float w = corner_areas[fi][corner % 3];
            sum += w * transform_dcurv(vertex_in_face(fits, fi, u, v, normals[vi]), face_dcurv[fi]);
            wsum += w;
        }
        if (!(wsum > 0)) return;
        // (d1, d2) = (c u - s v, s u + c v) in (u, v).
        const float c = glm::dot(d1[vi], u), s = -glm::dot(d1[vi], v);
        dcurv[vi] = transform_dcurv(FrameChange{c, -s, s, c}, sum / wsum);
    });
    return dcurv;
}

}  // namespace kappa
