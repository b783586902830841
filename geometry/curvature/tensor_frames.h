// Moving curvature tensors and their derivatives between tangent frames
// (Rusinkiewicz 2004, sec. 3.3): a frame (u, v) is first rotated rigidly
// about the common axis so that it lies in the plane of the other frame,
// then the tensor is re-expressed there. This rotation is what avoids the
// cos^2 loss of a plain projection.
#pragma once

#include "geometry/parallel/double_lanes.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <utility>

namespace kappa {

// Symmetric 2x2 tensor [[ku, kuv], [kuv, kv]] in some frame (u, v).
struct Tensor2 {
    float ku = 0, kuv = 0, kv = 0;
};

// A right-handed unit tangent frame for normal n: u x v = n (Duff et al.
// 2017, "Building an orthonormal basis, revisited"). Depends on n only. In
// any number type of lanes.h / double_lanes.h (the same operations, lane by
// lane), and for glm vectors below.
template <typename D>
KAPPA_LANES_INLINE void tangent_frame(const lanes::Vec3<D>& n, lanes::Vec3<D>& u, lanes::Vec3<D>& v) {
    const D sign = lanes::sign_of<D>(n.z);
    const D a = -1 / (sign + n.z);
    const D b = n.x * n.y * a;
    u = {1 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    v = {b, sign + n.y * n.y * a, -n.y};
}
inline void tangent_frame(const glm::vec3& n, glm::vec3& u, glm::vec3& v) {
    lanes::Vec3<float> fu, fv;
    tangent_frame<float>({n.x, n.y, n.z}, fu, fv);
    u = {fu.x, fu.y, fu.z};
    v = {fv.x, fv.y, fv.z};
}

// Rotates the frame (u, v) about the axis u x v (its normal) x new_normal so
// that its normal becomes new_normal (trimesh2's rot_coord_sys).
inline void rotate_frame(const glm::vec3& u, const glm::vec3& v, const glm::vec3& new_normal,
                         glm::vec3& ru, glm::vec3& rv) {
    ru = u;
    rv = v;
    const glm::vec3 old_normal = glm::cross(u, v);
    const float ndot = glm::dot(old_normal, new_normal);
    if (ndot <= -1.0f) {  // opposite normals: a half turn
        ru = -ru;
        rv = -rv;
        return;
    }
    const glm::vec3 perp_old = new_normal - ndot * old_normal;
    const glm::vec3 dperp = (old_normal + new_normal) / (1.0f + ndot);
    ru -= dperp * glm::dot(ru, perp_old);
    rv -= dperp * glm::dot(rv, perp_old);
}

// Re-expresses tensor t, given in frame (old_u, old_v), in frame (new_u,
// new_v) after rotating the new frame into the old frame's plane.
inline Tensor2 project_tensor(const glm::vec3& old_u, const glm::vec3& old_v, const Tensor2& t,
                              const glm::vec3& new_u, const glm::vec3& new_v) {
    glm::vec3 ru, rv;
    rotate_frame(new_u, new_v, glm::cross(old_u, old_v), ru, rv);
    const float u1 = glm::dot(ru, old_u), v1 = glm::dot(ru, old_v);
    const float u2 = glm::dot(rv, old_u), v2 = glm::dot(rv, old_v);
    Tensor2 r;
    r.ku = t.ku * u1 * u1 + t.kuv * (2.0f * u1 * v1) + t.kv * v1 * v1;
    r.kuv = t.ku * u1 * u2 + t.kuv * (u1 * v2 + u2 * v1) + t.kv * v1 * v2;
    r.kv = t.ku * u2 * u2 + t.kuv * (2.0f * u2 * v2) + t.kv * v2 * v2;
    return r;
}

// The symmetric trilinear form C(x, y, z) for 2-vectors, with C stored as
// (a, b, c, d) = (C111, C112, C122, C222) (conventions.md).
inline float trilinear(const glm::vec4& C, float x1, float x2, float y1, float y2, float z1, float z2) {
    return C[0] * x1 * y1 * z1 +
           C[1] * (x1 * y1 * z2 + x1 * y2 * z1 + x2 * y1 * z1) +
           C[2] * (x1 * y2 * z2 + x2 * y1 * z2 + x2 * y2 * z1) +
           C[3] * x2 * y2 * z2;
}

// Re-expresses the derivative-of-curvature tensor C, given in (old_u,
// old_v), in (new_u, new_v), rotating as project_tensor does.
inline glm::vec4 project_dcurv(const glm::vec3& old_u, const glm::vec3& old_v, const glm::vec4& C,
                               const glm::vec3& new_u, const glm::vec3& new_v) {
    glm::vec3 ru, rv;
    rotate_frame(new_u, new_v, glm::cross(old_u, old_v), ru, rv);
    const float u1 = glm::dot(ru, old_u), v1 = glm::dot(ru, old_v);
    const float u2 = glm::dot(rv, old_u), v2 = glm::dot(rv, old_v);
    return {trilinear(C, u1, v1, u1, v1, u1, v1), trilinear(C, u1, v1, u1, v1, u2, v2),
            trilinear(C, u1, v1, u2, v2, u2, v2), trilinear(C, u2, v2, u2, v2, u2, v2)};
}

// A change of 2D frame given by the new basis vectors' coordinates in the
// old basis: new_x = m00 old_x + m01 old_y, new_y = m10 old_x + m11 old_y.
struct FrameChange {
    float m00 = 1, m01 = 0, m10 = 0, m11 = 1;
};

// A change of frame that is a rotation by angle phi: new x = c old x + s
// old y, new y = -s old x + c old y. Kept per (vertex, face) corner.
struct FrameRotation {
    float c, s;
    FrameChange change() const { return {c, s, -s, c}; }
};

// The vertex frame (u, v) (normal nv = u x v), rotated into the plane of the
// face frame (t, b) (normal nf = t x b) by rotate_frame, as a rotation from
// (t, b): (c, s) = (rotated u . t, rotated u . b), the coefficients
// project_tensor computes, in closed form (rotated v is nv turned into nf,
// so (-s, c)). With k = 1 / (1 + nv.nf), rotate_frame maps x (tangent to nv)
// to x - (nv + nf) k (x.nf), and t.nf = b.nf = 0. Where nv = -nf exactly,
// rotate_frame's axis is undefined; a half turn about t is taken
// (u -> (u.t, -u.b)): a proper rotation onto nf, where a half turn about nv
// would be a reflection. Per lane, as tangent_frame.
template <typename D>
KAPPA_LANES_INLINE void frame_rotation(const lanes::Vec3<D>& t, const lanes::Vec3<D>& b, const lanes::Vec3<D>& nf,
                                       const lanes::Vec3<D>& u, const lanes::Vec3<D>& nv, D& c, D& s) {
    using lanes::dot;
    const D ndot = dot(nv, nf), ut = dot(u, t), ub = dot(u, b);
    const D un = dot(u, nf) / (1 + ndot);
    const lanes::Mask<D> opposite = ndot <= -1;
    c = lanes::select<D>(opposite, ut, ut - dot(nv, t) * un);
    s = lanes::select<D>(opposite, -ub, ub - dot(nv, b) * un);
}

// T in the new frame: M T M^T.
inline Tensor2 transform_tensor(const FrameChange& m, const Tensor2& t) {
    const float x0 = t.ku * m.m00 + t.kuv * m.m01, y0 = t.kuv * m.m00 + t.kv * m.m01;  // T m0
    const float x1 = t.ku * m.m10 + t.kuv * m.m11, y1 = t.kuv * m.m10 + t.kv * m.m11;  // T m1
    return {m.m00 * x0 + m.m01 * y0, m.m10 * x0 + m.m11 * y0, m.m10 * x1 + m.m11 * y1};
}

// C in the new frame: (C(m0,m0,m0), C(m0,m0,m1), C(m0,m1,m1), C(m1,m1,m1)).
// C(x) = [[a x1 + b x2, b x1 + c x2], [b x1 + c x2, c x1 + d x2]] is C with
// one slot filled; then C(x, y, z) = y^T C(x) z.
inline glm::vec4 transform_dcurv(const FrameChange& m, const glm::vec4& C) {
    // C(m0) and C(m1) as [[x00, x01], [x01, x11]].
    const float p00 = C[0] * m.m00 + C[1] * m.m01, p01 = C[1] * m.m00 + C[2] * m.m01,
                p11 = C[2] * m.m00 + C[3] * m.m01;
    const float r00 = C[0] * m.m10 + C[1] * m.m11, r01 = C[1] * m.m10 + C[2] * m.m11,
                r11 = C[2] * m.m10 + C[3] * m.m11;
    const float a0 = p00 * m.m00 + p01 * m.m01, a1 = p01 * m.m00 + p11 * m.m01;  // C(m0) m0
    const float b0 = p00 * m.m10 + p01 * m.m11, b1 = p01 * m.m10 + p11 * m.m11;  // C(m0) m1
    const float c0 = r00 * m.m10 + r01 * m.m11, c1 = r01 * m.m10 + r11 * m.m11;  // C(m1) m1
    return {m.m00 * a0 + m.m01 * a1, m.m10 * a0 + m.m11 * a1, m.m10 * b0 + m.m11 * b1,
            m.m10 * c0 + m.m11 * c1};
}

// A tensor by its harmonics: on the unit circle x = (cos t, sin t),
//   T(x, x) = h0 + a2 cos 2t + b2 sin 2t,  (h0, a2, b2) = ((ku + kv) / 2, (ku - kv) / 2, kuv).
// A frame turned by phi turns (a2, b2) by -2 phi (h0, the mean curvature,
// does not change): cheaper than transform_tensor, and linear.
// In any number type or lanes (the face fits form them in double), and for Tensor2.
template <typename T> KAPPA_LANES_INLINE void tensor_harmonics(T ku, T kuv, T kv, T (&h)[3]) {
    const lanes::Scalar<T> half = 0.5;
    h[0] = half * (ku + kv);
    h[1] = half * (ku - kv);
    h[2] = kuv;
}
inline glm::vec3 tensor_harmonics(const Tensor2& t) {
    float h[3];
    tensor_harmonics<float>(t.ku, t.kuv, t.kv, h);
    return {h[0], h[1], h[2]};
}
inline Tensor2 tensor_from_harmonics(const glm::vec3& h) { return {h[0] + h[1], h[2], h[0] - h[1]}; }
// The harmonics in the frame turned by phi, (c, s) = (cos phi, sin phi), c^2 + s^2 = 1:
// (h0, a2 cos 2phi + b2 sin 2phi, b2 cos 2phi - a2 sin 2phi), as lanes (h0, a2, b2, any),
// lane 3 of the result 0 (for finite input).
inline lanes::Lanes turn_tensor_harmonics(lanes::Lanes h, float c, float s) {
    const float c2 = c * c - s * s, s2 = 2.0f * c * s;  // cos 2phi, sin 2phi
    const lanes::Lanes swapped = __builtin_shufflevector(h, h, 0, 2, 1, 3);
    return h * lanes::Lanes{1, c2, c2, 0} + swapped * lanes::Lanes{0, s2, -s2, 0};
}
inline glm::vec3 turn_tensor_harmonics(const glm::vec3& h, float c, float s) {
    const lanes::Lanes r = turn_tensor_harmonics(lanes::Lanes{h[0], h[1], h[2], 0}, c, s);
    return {r[0], r[1], r[2]};
}

// C by its harmonics: on the unit circle x = (cos t, sin t),
//   C(x, x, x) = a1 cos t + b1 sin t + a3 cos 3t + b3 sin 3t,
// with (a1, b1, a3, b3) = (3 (a + c) / 4, 3 (b + d) / 4, (a - 3c) / 4, (3b - d) / 4)
// for C = (a, b, c, d). A frame turned by phi turns (a1, b1) by -phi and
// (a3, b3) by -3 phi: four rotations' worth of arithmetic where
// transform_dcurv takes three times as much, and linear, so sums of C in
// one frame can be turned once.
// In any number type or lanes (the face fits form them in double), and for glm.
template <typename T> KAPPA_LANES_INLINE void dcurv_harmonics(const T (&C)[4], T (&h)[4]) {
    using S = lanes::Scalar<T>;
    const S three_quarters = 0.75, quarter = 0.25, three = 3.0;
    h[0] = three_quarters * (C[0] + C[2]);
    h[1] = three_quarters * (C[1] + C[3]);
    h[2] = quarter * (C[0] - three * C[2]);
    h[3] = quarter * (three * C[1] - C[3]);
}
inline glm::vec4 dcurv_harmonics(const glm::vec4& C) {
    const float c[4] = {C[0], C[1], C[2], C[3]};
    float h[4];
    dcurv_harmonics<float>(c, h);
    return {h[0], h[1], h[2], h[3]};
}
inline glm::vec4 dcurv_from_harmonics(const glm::vec4& h) {
    return {h[0] + h[2], h[1] / 3.0f + h[3], h[0] / 3.0f - h[2], h[1] - h[3]};
}
// The harmonics of C in the frame turned by phi, (c, s) = (cos phi, sin phi)
// (FrameRotation's new x axis), c^2 + s^2 = 1.
// (a1 c + b1 s, b1 c - a1 s, a3 c3 + b3 s3, b3 c3 - a3 s3), c3 and s3 those of 3 phi: as
// lanes, and for glm.
inline lanes::Lanes turn_dcurv_harmonics(lanes::Lanes h, float c, float s) {
    const float c3 = c * (4.0f * c * c - 3.0f), s3 = s * (3.0f - 4.0f * s * s);  // cos 3phi, sin 3phi
    const lanes::Lanes swapped = __builtin_shufflevector(h, h, 1, 0, 3, 2);
    return h * lanes::Lanes{c, c, c3, c3} + swapped * lanes::Lanes{s, -s, s3, -s3};
}
inline glm::vec4 turn_dcurv_harmonics(const glm::vec4& h, float c, float s) {
    const lanes::Lanes r = turn_dcurv_harmonics(lanes::Lanes{h[0], h[1], h[2], h[3]}, c, s);
    return {r[0], r[1], r[2], r[3]};
}

// Eigen-decomposition of tensor t in frame (u, v) with normal n = u x v by
// one Jacobi rotation: k1 >= k2 (signed), d1 x d2 = n.
inline void diagonalize_tensor(const glm::vec3& u, const glm::vec3& v, const glm::vec3& n, const Tensor2& t,
                               glm::vec3& d1, glm::vec3& d2, float& k1, float& k2) {
    float c = 1, s = 0, tt = 0;
    if (t.kuv != 0.0f) {
        const float h = 0.5f * (t.kv - t.ku) / t.kuv;
        tt = (h < 0.0f) ? 1.0f / (h - std::sqrt(1.0f + h * h)) : 1.0f / (h + std::sqrt(1.0f + h * h));
        c = 1.0f / std::sqrt(1.0f + tt * tt);
        s = tt * c;
    }
    k1 = t.ku - tt * t.kuv;  // eigenvalue along c u - s v
    k2 = t.kv + tt * t.kuv;  // eigenvalue along s u + c v
    if (k1 >= k2) {
        d1 = c * u - s * v;
    } else {
        std::swap(k1, k2);
        d1 = s * u + c * v;
    }
    d2 = glm::cross(n, d1);
}

}  // namespace kappa
