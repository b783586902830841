#include "dcurvature.h"

#include "geometry/parallel/double_lanes.h"
#include "ldlt.h"
#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

namespace kappa {

namespace {

// C on faces first .. first + L - 1, L the lanes of D (double_lanes.h),
// replacing their fits (FaceRecord::fit); faces whose fit fails get weight 0.
// The vertices' tensors are turned into the face frame by the inverse
// (transposed) corner rotation, then C is fitted to their differences along
// the edges, the kuv equation counted twice (kuv appears twice in the
// tensor): normal equations, SPD and tridiagonal,
// [[uu, uv, 0, 0], [uv, 2uu + vv, 2uv, 0], [0, 2uv, uu + 2vv, uv], [0, 0, uv, vv]] (a, b, c, d)^T = m.
// Faces not usable are computed too: their records are all zero (so is
// what is stored back) and their indices valid.
template <typename D>
KAPPA_LANES_INLINE void fit_dcurv_faces(const Mesh& mesh, const std::vector<Tensor2>& tensors, size_t first,
                                        FaceRecord* fits) {
    using namespace lanes;
    using F = FloatsFor<D>;
    const auto record = [&](int j) { return reinterpret_cast<const float*>(&fits[j]); };  // FaceRecord's 16 floats
    const Vec3<D> edges = widen3<D>(load3<D>([&](int j) { return record(j) + 3; }));
    const D u[3] = {edges.x, edges.y, -edges.x - edges.y}, v[3] = {D{}, edges.z, -edges.z};
    D ku[3], kuv[3], kv[3];  // the corners' tensors in the face frame
    F c0{};                  // corner 0's c, stored back unchanged after the weights
    for (int k = 0; k < 3; ++k) {
        const Vec3<D> t = widen3<D>(load3<D>([&](int j) { return &tensors[mesh.faces[first + j][k]].ku; }));
        F fc, fs;
        load2<D>([&](int j) { return record(j) + 9 + 2 * k; }, fc, fs);
        if (k == 0) c0 = fc;
        const D c = widen<D>(fc), s = widen<D>(fs);
        // transform_tensor by the transposed rotation, rows (c, -s) and (s, c): M T M^T.
        const D x0 = t.x * c - t.y * s, y0 = t.y * c - t.z * s;
        const D x1 = t.x * s + t.y * c, y1 = t.y * s + t.z * c;
        ku[k] = c * x0 - s * y0;
        kuv[k] = s * x0 + c * y0;
        kv[k] = s * x1 + c * y1;
    }
    D m[4] = {}, uu{}, uv{}, vv{};
    for (int j = 0; j < 3; ++j) {
        const int prev = (j + 2) % 3, next = (j + 1) % 3;
        const D dku = ku[prev] - ku[next], dkuv = kuv[prev] - kuv[next], dkv = kv[prev] - kv[next];
        uu += u[j] * u[j];
        uv += u[j] * v[j];
        vv += v[j] * v[j];
        m[0] += u[j] * dku;
        m[1] += v[j] * dku + 2.0 * u[j] * dkuv;
        m[2] += 2.0 * v[j] * dkuv + u[j] * dkv;
        m[3] += v[j] * dkv;
    }
    const D diag[4] = {uu, 2.0 * uu + vv, uu + 2.0 * vv, vv}, off[3] = {uv, 2.0 * uv, uv};
    D x[4];
    const FloatMask<D> ok = narrow_mask<D>(ldlt_solve_tridiagonal_lanes<4, D>(diag, off, m, x));
    // C's harmonics (dcurv_harmonics) replace the fit; a face whose fit
    // failed gets weight 0 (unusable faces have weight 0 already).
    D h[4];
    dcurv_harmonics<D>(x, h);
    const Vec3<F> w = load3<D>([&](int j) { return record(j) + 6; });
    const F harmonics[4] = {keep<D>(ok, narrow<D>(h[0])), keep<D>(ok, narrow<D>(h[1])), keep<D>(ok, narrow<D>(h[2])),
                            keep<D>(ok, narrow<D>(h[3]))};
    const F weights_c0[4] = {keep<D>(ok, w.x), keep<D>(ok, w.y), keep<D>(ok, w.z), c0};
    store4<D>(harmonics, reinterpret_cast<float*>(fits));
    store4<D>(weights_c0, reinterpret_cast<float*>(fits) + 6);
}

}  // namespace

std::vector<glm::vec4> compute_dcurv(const Mesh& mesh, const VertexFaces& vf, FaceRecords fits,
                                     const std::vector<glm::vec3>& normals, VertexTensors tensors,
                                     const std::vector<glm::vec3>& d1) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    parallel_for_chunks(nf, [&](size_t first, size_t last) {
        lanes::for_each_group(first, last, [&](auto lanes, size_t i) KAPPA_LANES_LAMBDA {
            fit_dcurv_faces<decltype(lanes)>(mesh, tensors.tensor, i, &fits[i]);
        });
    });
    std::vector<Tensor2>().swap(tensors.tensor);

    std::vector<glm::vec4> dcurv(nv, glm::vec4(0.0f));
    parallel_for_chunked(nv, [&](size_t vi) {
        // Average in the vertex frame (u, v), as harmonics (tensor_frames.h),
        // then turn the (linear) result into the principal frame.
        lanes::Lanes sum{};
        const float wsum = add_face_values(vf, fits, vi, sum, [](lanes::Lanes fit, const FrameRotation& r) {
            return turn_dcurv_harmonics(fit, r.c, r.s);
        });
        if (!(wsum > 0)) return;
        // d1 = c u + s v: the principal frame is (u, v) turned by atan2(s, c).
        glm::vec3 u, v;
        tangent_frame(normals[vi], u, v);
        const float c = glm::dot(d1[vi], u), s = glm::dot(d1[vi], v);
        dcurv[vi] = dcurv_from_harmonics(turn_dcurv_harmonics(glm::vec4(sum[0], sum[1], sum[2], sum[3]) / wsum, c, s));
    });
    return dcurv;
}

}  // namespace kappa
