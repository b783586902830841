#include "curvature.h"

#include "ldlt.h"
#include "parallel.h"
#include "prefetch.h"

#include <glm/geometric.hpp>

namespace kappa {

namespace {

// Least-squares fit of II in the face frame (sec. 3.2): each edge e_j
// (opposite corner j) with coordinates (u_j, v_j) in (t, b) should satisfy
// II (u, v)^T = (dn.t, dn.b), dn the normal difference along that edge.
// The normal equations in (e, f, g) form a 3x3 SPD system.
bool fit_face_tensor(const double (&u)[3], const double (&v)[3], const glm::dvec3 (&dn)[3], const glm::dvec3& t,
                     const glm::dvec3& b, Tensor2& out) {
    // Normal equations [[uu, uv, 0], [uv, uu + vv, uv], [0, uv, vv]] (e, f, g)^T = m.
    double uu = 0, uv = 0, vv = 0, m[3] = {};
    for (int j = 0; j < 3; ++j) {
        const double dnu = glm::dot(dn[j], t), dnv = glm::dot(dn[j], b);
        uu += u[j] * u[j];
        uv += u[j] * v[j];
        vv += v[j] * v[j];
        m[0] += dnu * u[j];
        m[1] += dnu * v[j] + dnv * u[j];
        m[2] += dnv * v[j];
    }
    const double diag[3] = {uu, uu + vv, vv}, off[2] = {uv, uv};
    double x[3];
    if (!ldlt_solve_tridiagonal<3>(diag, off, m, x)) return false;
    out = {float(x[0]), float(x[1]), float(x[2])};
    return true;
}

// Face i's record; all weights 0 (unusable) when degenerate or the fit fails.
FaceFit fit_face(const Mesh& mesh, const std::vector<glm::vec3>& normals, const FaceGeometry& faces, size_t i) {
    FaceFit fit{};  // all 0: not usable
    if (faces.degenerate(i)) return fit;
    prefetch_corners_ahead(mesh, i, mesh.positions.data(), normals.data());
    const Face& f = mesh.faces[i];
    const glm::dvec3 p[3] = {mesh.positions[f[0]], mesh.positions[f[1]], mesh.positions[f[2]]};
    const glm::dvec3 e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};  // e[j] opposite corner j
    const glm::dvec3 t = glm::normalize(e[0]);
    const glm::dvec3 n = glm::normalize(glm::dvec3(faces.area_normals[i]));
    const glm::dvec3 b = glm::cross(n, t);
    const double u[3] = {glm::dot(e[0], t), glm::dot(e[1], t), glm::dot(e[2], t)};
    const double v[3] = {glm::dot(e[0], b), glm::dot(e[1], b), glm::dot(e[2], b)};
    const glm::vec3 vn[3] = {normals[f[0]], normals[f[1]], normals[f[2]]};
    const glm::dvec3 dn[3] = {glm::dvec3(vn[2]) - glm::dvec3(vn[1]), glm::dvec3(vn[0]) - glm::dvec3(vn[2]),
                              glm::dvec3(vn[1]) - glm::dvec3(vn[0])};
    Tensor2 tensor;
    if (!fit_face_tensor(u, v, dn, t, b, tensor)) return fit;
    const float values[6] = {tensor.ku, tensor.kuv, tensor.kv, float(u[0]), float(u[1]), float(v[1])};
    for (int k = 0; k < 6; ++k) fit.fit[k] = values[k];
    fit.weights = faces.corner_areas[i];
    for (int j = 0; j < 3; ++j) {
        glm::vec3 vu, vv;
        tangent_frame(vn[j], vu, vv);
        fit.corners[j] = frame_rotation(glm::vec3(t), glm::vec3(b), glm::vec3(n), vu, vn[j]);
    }
    return fit;
}

}  // namespace

VertexTensors compute_curvature_tensors(const Mesh& mesh, const VertexFaces& vf,
                                        const std::vector<glm::vec3>& normals, const FaceGeometry& faces,
                                        FaceFits& fits) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    fits = FaceFits(nf);
    parallel_for(nf, [&](size_t i) {
        fits[i] = fit_face(mesh, normals, faces, i);  // one store of the whole line
    });

    VertexTensors out;
    out.tensor.resize(nv);
    parallel_for(nv, [&](size_t vi) {
        float ku = 0, kuv = 0, kv = 0, wsum = 0;
        for (uint32_t k = vf.begin(vi); k < vf.end(vi); ++k) {
            const uint32_t c = vf.corners[k];
            prefetch_face_ahead(vf, k, fits.data());
            const FaceFit& fit = fits[c / 3];
            const float w = fit.weights[c % 3];
            if (!(w > 0)) continue;
            const Tensor2 r = transform_tensor(fit.corners[c % 3].change(), fit.tensor());
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
