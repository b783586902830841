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
    fits.corner_frames.resize(3 * nf);
    fits.corner_weights.assign(3 * nf, 0.0f);
    // Per corner: the face tensor in the corner vertex's frame, times the corner weight.
    std::vector<Tensor2> corner_tensor(3 * nf);

    parallel_for(nf, [&](size_t i) {
        const Face& f = mesh.faces[i];
        const glm::dvec3 p[3] = {mesh.positions[f[0]], mesh.positions[f[1]], mesh.positions[f[2]]};
        const glm::dvec3 e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};  // e[j] opposite corner j
        if (faces.degenerate(i)) return;
        const glm::dvec3 t = glm::normalize(e[0]);
        const glm::dvec3 n = glm::normalize(glm::dvec3(faces.area_normals[i]));
        const glm::dvec3 b = glm::cross(n, t);
        const glm::dvec3 dn[3] = {glm::dvec3(normals[f[2]]) - glm::dvec3(normals[f[1]]),
                                  glm::dvec3(normals[f[0]]) - glm::dvec3(normals[f[2]]),
                                  glm::dvec3(normals[f[1]]) - glm::dvec3(normals[f[0]])};
        Tensor2 face_tensor;
        if (!fit_face_tensor(e, dn, t, b, face_tensor)) return;
        fits.t[i] = glm::vec3(t);
        fits.b[i] = glm::vec3(b);
        const glm::vec3 nf(n);
        for (int j = 0; j < 3; ++j) {
            const glm::vec3& nv = normals[f[j]];
            glm::vec3 u, v;
            tangent_frame(nv, u, v);
            const FrameChange m = frame_change(fits.t[i], fits.b[i], nf, u, v, nv);
            const float w = faces.corner_areas[i][j];
            const Tensor2 r = transform_tensor(m, face_tensor);
            fits.corner_frames[3 * i + j] = m;
            fits.corner_weights[3 * i + j] = w;
            corner_tensor[3 * i + j] = {w * r.ku, w * r.kuv, w * r.kv};
        }
    });

    VertexTensors out;
    out.u.resize(nv);
    out.v.resize(nv);
    out.tensor.resize(nv);
    parallel_for(nv, [&](size_t vi) {
        tangent_frame(normals[vi], out.u[vi], out.v[vi]);
        double ku = 0, kuv = 0, kv = 0, wsum = 0;
        for (uint32_t k = vf.begin(vi); k < vf.end(vi); ++k) {
            const uint32_t c = vf.corners[k];
            ku += corner_tensor[c].ku;
            kuv += corner_tensor[c].kuv;
            kv += corner_tensor[c].kv;
            wsum += fits.corner_weights[c];
        }
        if (wsum > 0) out.tensor[vi] = {float(ku / wsum), float(kuv / wsum), float(kv / wsum)};
    });
    return out;
}

void principal_curvatures(const VertexTensors& tensors, std::vector<float>& k1, std::vector<float>& k2,
                          std::vector<glm::vec3>& d1, std::vector<glm::vec3>& d2) {
    const size_t nv = tensors.u.size();
    k1.resize(nv);
    k2.resize(nv);
    d1.resize(nv);
    d2.resize(nv);
    parallel_for(nv, [&](size_t i) {
        const glm::vec3 n = glm::cross(tensors.u[i], tensors.v[i]);
        diagonalize_tensor(tensors.u[i], tensors.v[i], n, tensors.tensor[i], d1[i], d2[i], k1[i], k2[i]);
    });
}

}  // namespace kappa
