#include "dcurvature.h"

#include "ldlt.h"
#include "parallel.h"
#include "prefetch.h"

#include <glm/geometric.hpp>

namespace kappa {

namespace {

// Normal equations of the fit in dcurvature.h, with the kuv equation counted twice
// (kuv appears twice in the tensor): a 4x4 SPD system in (a, b, c, d).
bool fit_face_dcurv(const glm::vec3& edges, const Tensor2 (&fcurv)[3], glm::vec4& out) {
    // Edge coordinates in (t, b), FaceFits::edges.
    const double u[3] = {edges.x, edges.y, -double(edges.x) - edges.y}, v[3] = {0, edges.z, -double(edges.z)};
    double m[4] = {}, uu = 0, uv = 0, vv = 0;
    for (int j = 0; j < 3; ++j) {
        const int prev = (j + 2) % 3, next = (j + 1) % 3;
        const double dku = double(fcurv[prev].ku) - fcurv[next].ku;
        const double dkuv = double(fcurv[prev].kuv) - fcurv[next].kuv;
        const double dkv = double(fcurv[prev].kv) - fcurv[next].kv;
        uu += u[j] * u[j];
        uv += u[j] * v[j];
        vv += v[j] * v[j];
        m[0] += u[j] * dku;
        m[1] += v[j] * dku + 2.0 * u[j] * dkuv;
        m[2] += 2.0 * v[j] * dkuv + u[j] * dkv;
        m[3] += v[j] * dkv;
    }
    // [[uu, uv, 0, 0], [uv, 2uu + vv, 2uv, 0], [0, 2uv, uu + 2vv, uv], [0, 0, uv, vv]] (a, b, c, d)^T = m
    const double diag[4] = {uu, 2 * uu + vv, uu + 2 * vv, vv}, off[3] = {uv, 2 * uv, uv};
    double x[4];
    if (!ldlt_solve_tridiagonal<4>(diag, off, m, x)) return false;
    out = glm::vec4(float(x[0]), float(x[1]), float(x[2]), float(x[3]));
    return true;
}

}  // namespace

std::vector<glm::vec4> compute_dcurv(const Mesh& mesh, const VertexFaces& vf, FaceFits fits,
                                     const std::vector<glm::vec3>& normals, VertexTensors tensors,
                                     const std::vector<glm::vec3>& d1) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    parallel_for(nf, [&](size_t i) {
        FaceFit& fit = fits[i];
        if (!fit.usable()) return;
        prefetch_corners_ahead(mesh, i, tensors.tensor.data());
        const Face& f = mesh.faces[i];
        // Vertex tensors in the face frame: the inverse (transposed) rotation.
        Tensor2 fcurv[3];
        for (int j = 0; j < 3; ++j)
            fcurv[j] = transform_tensor(fit.corners[j].change().transposed(), tensors.tensor[f[j]]);
        glm::vec4 C;
        if (fit_face_dcurv(fit.edges(), fcurv, C)) {
            for (int k = 0; k < 4; ++k) fit.fit[k] = C[k];
        } else {
            fit.weights = glm::vec3(0.0f);
        }
    });
    std::vector<Tensor2>().swap(tensors.tensor);

    std::vector<glm::vec4> dcurv(nv, glm::vec4(0.0f));
    parallel_for(nv, [&](size_t vi) {
        // Average in the vertex frame (u, v), then turn the (linear) result into the principal frame.
        glm::vec4 sum(0.0f);
        float wsum = 0;
        for (uint32_t k = vf.begin(vi); k < vf.end(vi); ++k) {
            const uint32_t c = vf.corners[k];
            prefetch_face_ahead(vf, k, fits.data());
            const FaceFit& fit = fits[c / 3];
            const float w = fit.weights[c % 3];
            if (!(w > 0)) continue;
            sum += w * transform_dcurv(fit.corners[c % 3].change(), fit.dcurv());
            wsum += w;
        }
        if (!(wsum > 0)) return;
        // (d1, d2) = (c u - s v, s u + c v) in (u, v).
        glm::vec3 u, v;
        tangent_frame(normals[vi], u, v);
        const float c = glm::dot(d1[vi], u), s = -glm::dot(d1[vi], v);
        dcurv[vi] = transform_dcurv(FrameChange{c, -s, s, c}, sum / wsum);
    });
    return dcurv;
}

}  // namespace kappa
