#include "dcurvature.h"

#include "ldlt.h"
#include "parallel.h"

#include <glm/geometric.hpp>

namespace kappa {

namespace {

// Normal equations of the fit above, with the kuv equation counted twice
// (kuv appears twice in the tensor): a 4x4 SPD system in (a, b, c, d).
bool fit_face_dcurv(const Mesh& mesh, size_t i, const FaceFrames& frames, const std::vector<float>& k1,
                    const std::vector<float>& k2, const std::vector<glm::vec3>& d1,
                    const std::vector<glm::vec3>& d2, glm::vec4& out) {
    const Face& f = mesh.faces[i];
    const glm::vec3 t = frames.t[i], b = frames.b[i];
    Tensor2 fcurv[3];
    for (int j = 0; j < 3; ++j) {
        const uint32_t v = f[j];
        fcurv[j] = project_tensor(d1[v], d2[v], Tensor2{k1[v], 0.0f, k2[v]}, t, b);
    }
    double w[4][4] = {}, m[4] = {};
    double uu = 0, uv = 0, vv = 0;
    for (int j = 0; j < 3; ++j) {
        const int prev = (j + 2) % 3, next = (j + 1) % 3;
        const glm::dvec3 e = glm::dvec3(mesh.positions[f[prev]]) - glm::dvec3(mesh.positions[f[next]]);
        const double u = glm::dot(e, glm::dvec3(t)), v = glm::dot(e, glm::dvec3(b));
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
    w[0][0] = uu;
    w[0][1] = w[1][0] = uv;
    w[1][1] = 2.0 * uu + vv;
    w[1][2] = w[2][1] = 2.0 * uv;
    w[2][2] = uu + 2.0 * vv;
    w[2][3] = w[3][2] = uv;
    w[3][3] = vv;
    double x[4];
    if (!ldlt_solve(w, m, x)) return false;
    out = glm::vec4(float(x[0]), float(x[1]), float(x[2]), float(x[3]));
    return true;
}

}  // namespace

std::vector<glm::vec4> compute_dcurv(const Mesh& mesh, const VertexFaces& vf, const FaceFrames& frames,
                                     const std::vector<glm::vec3>& corner_areas, const std::vector<float>& k1,
                                     const std::vector<float>& k2, const std::vector<glm::vec3>& d1,
                                     const std::vector<glm::vec3>& d2) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    std::vector<glm::vec4> face_dcurv(nf);
    std::vector<uint8_t> face_ok(nf, 0);
    parallel_for(nf, [&](size_t i) {
        if (!frames.degenerate(i)) face_ok[i] = fit_face_dcurv(mesh, i, frames, k1, k2, d1, d2, face_dcurv[i]);
    });

    std::vector<glm::vec4> dcurv(nv, glm::vec4(0.0f));
    parallel_for(nv, [&](size_t vi) {
        glm::dvec4 sum(0.0);
        double wsum = 0;
        for (uint32_t k = vf.begin(vi); k < vf.end(vi); ++k) {
            const uint32_t c = vf.corners[k], fi = c / 3;
            if (!face_ok[fi]) continue;
            const double wt = corner_areas[fi][c % 3];
            if (!(wt > 0)) continue;
            sum += wt * glm::dvec4(project_dcurv(frames.t[fi], frames.b[fi], face_dcurv[fi], d1[vi], d2[vi]));
            wsum += wt;
        }
        if (wsum > 0) dcurv[vi] = glm::vec4(sum / wsum);
    });
    return dcurv;
}

}  // namespace kappa
