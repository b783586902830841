#include "curvature.h"

#include "geometry/parallel/double_lanes.h"
#include "ldlt.h"
#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

namespace kappa {

namespace {

// Faces first .. first + L - 1, L the lanes of D (double_lanes.h: four
// faces at once, or one), into out[0 .. L). Per face:
//  - the least-squares fit of II in the face frame (t, b) (sec. 3.2): each
//    edge e_j (opposite corner j) with coordinates (u_j, v_j) should satisfy
//    II (u_j, v_j)^T = (dn_j.t, dn_j.b), dn_j the normal difference along it;
//    normal equations [[uu, uv, 0], [uv, uu + vv, uv], [0, uv, vv]] (e, f, g)^T = m;
//  - each corner's vertex frame rotated into the face plane (frame_rotation).
// Degenerate faces are stored unusable.
template <typename D>
KAPPA_LANES_INLINE void fit_faces(const Mesh& mesh, const std::vector<glm::vec3>& normals, size_t first,
                                  FaceRecord* out) {
    using namespace lanes;
    using F = FloatsFor<D>;
    // Degenerate faces are computed too (their records are stored all 0):
    // their indices are valid, and whatever their numbers give is dropped.
    Vec3<D> p[3], vn[3];
    for (int c = 0; c < 3; ++c) {
        p[c] = widen3<D>(load3<D>([&](int j) { return &mesh.positions[mesh.faces[first + j][c]].x; }));
        vn[c] = widen3<D>(load3<D>([&](int j) { return &normals[mesh.faces[first + j][c]].x; }));
    }
    const Vec3<D> e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};  // e[j] opposite corner j
    const Vec3<D> t = normalize(e[0]);
    const Vec3<D> n = normalize(widen3<D>(load3<D>([&](int j) { return &out[j].fit[0]; })));  // the area normal
    const Vec3<D> b = cross(n, t);
    const Vec3<D> dn[3] = {vn[2] - vn[1], vn[0] - vn[2], vn[1] - vn[0]};
    D u[3], v[3], uu{}, uv{}, vv{}, m[3] = {};
    for (int j = 0; j < 3; ++j) {
        u[j] = dot(e[j], t);
        v[j] = dot(e[j], b);
        const D dnu = dot(dn[j], t), dnv = dot(dn[j], b);
        uu += u[j] * u[j];
        uv += u[j] * v[j];
        vv += v[j] * v[j];
        m[0] += dnu * u[j];
        m[1] += dnu * v[j] + dnv * u[j];
        m[2] += dnv * v[j];
    }
    const D diag[3] = {uu, uu + vv, vv}, off[2] = {uv, uv};
    D x[3];
    const Mask<D> ok = ldlt_solve_tridiagonal_lanes<3, D>(diag, off, m, x);
    // Corner k's vertex frame, rotated into the face plane.
    D c[3], s[3];
    for (int k = 0; k < 3; ++k) {
        Vec3<D> fu, fv;
        tangent_frame<D>(vn[k], fu, fv);
        frame_rotation<D>(t, b, n, fu, vn[k], c[k], s[k]);
    }
    // The records, lane j into out[j]: FaceRecord's 16 floats in order, all 0
    // where the face is degenerate (corner areas all 0) or its fit failed.
    const Vec3<F> w = load3<D>([&](int j) { return &out[j].weights.x; });  // the corner areas
    const FloatMask<D> usable = narrow_mask<D>(ok) & ((w.x != 0.0f) | (w.y != 0.0f) | (w.z != 0.0f));
    D h[3];
    tensor_harmonics<D>(x[0], x[1], x[2], h);
    const F record[16] = {narrow<D>(h[0]), narrow<D>(h[1]), narrow<D>(h[2]), narrow<D>(u[0]),
                          narrow<D>(u[1]), narrow<D>(v[1]), w.x,             w.y,
                          w.z,             narrow<D>(c[0]), narrow<D>(s[0]), narrow<D>(c[1]),
                          narrow<D>(s[1]), narrow<D>(c[2]), narrow<D>(s[2]), F{}};
    for (int k = 0; k < 16; k += 4) {
        const F kept[4] = {keep<D>(usable, record[k]), keep<D>(usable, record[k + 1]),
                           keep<D>(usable, record[k + 2]), keep<D>(usable, record[k + 3])};
        store4<D>(kept, reinterpret_cast<float*>(out) + k);
    }
}

}  // namespace

VertexTensors compute_curvature_tensors(const Mesh& mesh, const VertexFaces& vf,
                                        const std::vector<glm::vec3>& normals, FaceRecords& records) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    FaceRecords& fits = records;  // each face's fit written over its geometry
    parallel_for_chunks(nf, [&](size_t first, size_t last) {
        lanes::for_each_group(first, last, [&](auto lanes, size_t i) KAPPA_LANES_LAMBDA {
            fit_faces<decltype(lanes)>(mesh, normals, i, &fits[i]);
        });
    });

    VertexTensors out;
    out.tensor.resize(nv);
    parallel_for_chunked(nv, [&](size_t vi) {
        // Summed as harmonics (tensor_frames.h) in the vertex frame.
        lanes::Lanes sum{};
        const float wsum = add_face_values(vf, fits, vi, sum, [](lanes::Lanes fit, const FrameRotation& r) {
            return turn_tensor_harmonics(fit, r.c, r.s);  // (h0, a2, b2, edge): the edge lane turns to 0
        });
        if (wsum > 0) out.tensor[vi] = tensor_from_harmonics(glm::vec3(sum[0], sum[1], sum[2]) / wsum);
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
