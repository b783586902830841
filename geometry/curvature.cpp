#include "curvature.h"

#include "ldlt.h"
#include "parallel.h"

#include <glm/geometric.hpp>

namespace kappa {

namespace {

// Least-squares fit of II in the face frame (sec. 3.2): each edge e_j
// (opposite corner j) with coordinates (u, v) in (t, b) should satisfy
// II (u, v)^T = (dn.t, dn.b), dn the normal difference along that edge.
// The normal equations in (e, f, g) form a 3x3 SPD system.
bool fit_face_tensor(const glm::dvec3 (&e)[3], const glm::dvec3 (&dn)[3], const glm::dvec3& t, const glm::dvec3& b,
                     Tensor2& out) {
    // Normal equations [[uu, uv, 0], [uv, uu + vv, uv], [0, uv, vv]] (e, f, g)^T = m.
    double uu = 0, uv = 0, vv = 0, m[3] = {};
    for (int j = 0; j < 3; ++j) {
        const double u = glm::dot(e[j], t), v = glm::dot(e[j], b);
        const double dnu = glm::dot(dn[j], t), dnv = glm::dot(dn[j], b);
        uu += u * u;
        uv += u * v;
        vv += v * v;
        m[0] += dnu * u;
        m[1] += dnu * v + dnv * u;
        m[2] += dnv * v;
    }
    const double diag[3] = {uu, uu + vv, vv}, off[2] = {uv, uv};
    double x[3];
    if (!ldlt_solve_tridiagonal<3>(diag, off, m, x)) return false;
    out = {float(x[0]), float(x[1]), float(x[2])};
    return true;
}

}  // namespace

VertexTensors compute_curvature_tensors(const Mesh& mesh, const VertexFaces& vf,
                                        const std::vector<glm::vec3>& normals, const FaceGeometry& faces,
                                        FaceFits& fits) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    fits.t.assign(nf, glm::vec3(0.0f));
    fits.b.assign(nf, glm::vec3(0.0f));
    fits.tensor.assign(nf, Tensor2{});
    fits.ok.assign(nf, 0);
    parallel_for(nf, [&](size_t i) {
        if (faces.degenerate(i)) return;
        const Face& f = mesh.faces[i];
        const glm::dvec3 p[3] = {mesh.positions[f[0]], mesh.positions[f[1]], mesh.positions[f[2]]};
        const glm::dvec3 e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};  // e[j] opposite corner j
        const glm::dvec3 t = glm::normalize(e[0]);
        const glm::dvec3 b = glm::cross(glm::normalize(glm::dvec3(faces.area_normals[i])), t);
        const glm::dvec3 dn[3] = {glm::dvec3(normals[f[2]]) - glm::dvec3(normals[f[1]]),
                                  glm::dvec3(normals[f[0]]) - glm::dvec3(normals[f[2]]),
                                  glm::dvec3(normals[f[1]]) - glm::dvec3(normals[f[0]])};
        if (!fit_face_tensor(e, dn, t, b, fits.tensor[i])) return;
        fits.t[i] = glm::vec3(t);
        fits.b[i] = glm::vec3(b);
        fits.ok[i] = 1;
    });

    VertexTensors out;
    out.tensor.resize(nv);
    parallel_for(nv, [&](size_t vi) {
        const glm::vec3 n = normals[vi];
        glm::vec3 u, v;
        tangent_frame(n, u, v);
        float ku = 0, kuv = 0, kv = 0, wsum = 0;
        for (uint32_t k = vf.begin(vi); k < vf.end(vi); ++k) {
            const uint32_t c = vf.corners[k], fi = c / 3;
            if (!fits.ok[fi]) continue;
            const float w = faces.corner_areas[fi][c % 3];
            const glm::vec3 &t = fits.t[fi], &b = fits.b[fi];
            const Tensor2 r = transform_tensor(frame_change(t, b, glm::cross(t, b), u, v, n), fits.tensor[fi]);
            ku += w * r.ku;
            kuv += w * r.kuv;
            kv += w * r.kv;
            wsum += w;
        }
        if (wsum > 0) out.tensor[vi] = {ku / wsum, kuv / wsum, kv / wsum};
    });
    return out;
}

void principal_curvatures(const VertexTensors& tensors, const std::vector<glm::vec3>& normals, std::vector<float>& k1,
                          std::vector<float>& k2, std::vector<glm::vec3>& d1) {
    const size_t nv = tensors.tensor.size();
    k1.resize(nv);
    k2.resize(nv);
    d1.resize(nv);
    parallel_for(nv, [&](size_t i) {
        glm::vec3 u, v, d2;
        tangent_frame(normals[i], u, v);
        diagonalize_tensor(u, v, normals[i], tensors.tensor[i], d1[i], d2, k1[i], k2[i]);
    });
}

std::vector<glm::vec3> second_principal_directions(const std::vector<glm::vec3>& normals,
                                                   const std::vector<glm::vec3>& d1) {
    std::vector<glm::vec3> d2(d1.size());
    parallel_for(d1.size(), [&](size_t i) { d2[i] = glm::cross(normals[i], d1[i]); });
    return d2;
}

}  // namespace kappa
