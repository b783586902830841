#include "curvature.h"

#include "degenerate.h"
#include "ldlt.h"
#include "parallel.h"

#include <glm/geometric.hpp>

namespace kappa {

FaceFrames compute_face_frames(const Mesh& mesh) {
    FaceFrames frames;
    frames.t.resize(mesh.face_count());
    frames.b.resize(mesh.face_count());
    parallel_for(mesh.face_count(), [&](size_t i) {
        const Face& f = mesh.faces[i];
        const glm::dvec3 p0 = mesh.positions[f[0]], p1 = mesh.positions[f[1]], p2 = mesh.positions[f[2]];
        const glm::dvec3 e0 = p2 - p1, e1 = p0 - p2, e2 = p1 - p0;
        if (is_degenerate_triangle(e0, e1, e2)) {
            frames.t[i] = frames.b[i] = glm::vec3(0.0f);
            return;
        }
        const glm::dvec3 t = glm::normalize(e0);
        const glm::dvec3 n = glm::normalize(glm::cross(e0, e1));
        frames.t[i] = glm::vec3(t);
        frames.b[i] = glm::vec3(glm::cross(n, t));
    });
    return frames;
}

namespace {

// Least-squares fit of II in the face frame (sec. 3.2): for each edge e_j
// (opposite corner j) with coordinates (u, v) in (t, b), II (u, v)^T should
// equal the normal difference (dn.t, dn.b) along that edge. The normal
// equations in (e, f, g) are a 3x3 SPD system.
bool fit_face_tensor(const Mesh& mesh, size_t i, const FaceFrames& frames, const std::vector<glm::vec3>& normals,
                     Tensor2& out) {
    const Face& f = mesh.faces[i];
    const glm::dvec3 t = frames.t[i], b = frames.b[i];
    double w[3][3] = {}, m[3] = {};
    for (int j = 0; j < 3; ++j) {
        const int prev = (j + 2) % 3, next = (j + 1) % 3;
        const glm::dvec3 e = glm::dvec3(mesh.positions[f[prev]]) - glm::dvec3(mesh.positions[f[next]]);
        const glm::dvec3 dn = glm::dvec3(normals[f[prev]]) - glm::dvec3(normals[f[next]]);
        const double u = glm::dot(e, t), v = glm::dot(e, b);
        const double dnu = glm::dot(dn, t), dnv = glm::dot(dn, b);
        w[0][0] += u * u;
        w[0][1] += u * v;
        w[2][2] += v * v;
        m[0] += dnu * u;
        m[1] += dnu * v + dnv * u;
        m[2] += dnv * v;
    }
    w[1][0] = w[0][1];
    w[1][1] = w[0][0] + w[2][2];
    w[1][2] = w[2][1] = w[0][1];
    double x[3];
    if (!ldlt_solve(w, m, x)) return false;
    out = {float(x[0]), float(x[1]), float(x[2])};
    return true;
}

}  // namespace

VertexTensors compute_curvature_tensors(const Mesh& mesh, const VertexFaces& vf, const FaceFrames& frames,
                                        const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec3>& corner_areas) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    // Step 1: one fit per face. A face whose fit fails gets zero corner weight.
    std::vector<Tensor2> face_tensor(nf);
    std::vector<uint8_t> face_ok(nf, 0);
    parallel_for(nf, [&](size_t i) {
        if (!frames.degenerate(i)) face_ok[i] = fit_face_tensor(mesh, i, frames, normals, face_tensor[i]);
    });

    // Step 2: gather into each vertex's frame, weighted by corner areas.
    VertexTensors out;
    out.u.resize(nv);
    out.v.resize(nv);
    out.tensor.resize(nv);
    parallel_for(nv, [&](size_t vi) {
        glm::vec3 u, v;
        tangent_frame(normals[vi] == glm::vec3(0.0f) ? glm::vec3(0, 0, 1) : normals[vi], u, v);
        double ku = 0, kuv = 0, kv = 0, wsum = 0;
        for (uint32_t k = vf.begin(vi); k < vf.end(vi); ++k) {
            const uint32_t c = vf.corners[k], fi = c / 3;
            if (!face_ok[fi]) continue;
            const double wt = corner_areas[fi][c % 3];
            if (!(wt > 0)) continue;
            const Tensor2 r = project_tensor(frames.t[fi], frames.b[fi], face_tensor[fi], u, v);
            ku += wt * r.ku;
            kuv += wt * r.kuv;
            kv += wt * r.kv;
            wsum += wt;
        }
        out.u[vi] = u;
        out.v[vi] = v;
        if (wsum > 0) out.tensor[vi] = {float(ku / wsum), float(kuv / wsum), float(kv / wsum)};
    });
    return out;
}

void principal_curvatures(const VertexTensors& tensors, std::vector<float>& k1, std::vector<float>& k2, std::vector<glm::vec3>& d1,
                          std::vector<glm::vec3>& d2) {
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
