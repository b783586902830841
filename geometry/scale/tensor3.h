// Curvature II and its derivative C as tensors of 3D space, so that values
// from different tangent frames can be summed directly. A 2D tensor in the
// tangent frame (u, v) embeds as T = sum T_ab e_a (x) e_b (e_1 = u,
// e_2 = v); restricting a 3D tensor to another frame evaluates it on that
// frame's vectors. Between nearly parallel tangent planes (neighbouring
// clusters, blended scales) this differs from the paper's rotation
// (tensor_frames.h) only to second order in the angle between them.
#pragma once

#include "geometry/curvature/tensor_frames.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace kappa {

// Symmetric 3x3 tensor: xx, xy, xz, yy, yz, zz.
struct Sym3 {
    float m[6] = {0, 0, 0, 0, 0, 0};
};

// Fully symmetric 3x3x3 tensor: xxx, xxy, xxz, xyy, xyz, xzz, yyy, yyz, yzz, zzz.
struct SymCubic3 {
    float c[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
};

inline float sym3_eval(const Sym3& t, const glm::vec3& a, const glm::vec3& b) {
    const float* m = t.m;
    return m[0] * a.x * b.x + m[3] * a.y * b.y + m[5] * a.z * b.z + m[1] * (a.x * b.y + a.y * b.x) +
           m[2] * (a.x * b.z + a.z * b.x) + m[4] * (a.y * b.z + a.z * b.y);
}

// T x.
inline glm::vec3 apply(const Sym3& t, const glm::vec3& x) {
    const float* m = t.m;
    return {m[0] * x.x + m[1] * x.y + m[2] * x.z, m[1] * x.x + m[3] * x.y + m[4] * x.z,
            m[2] * x.x + m[4] * x.y + m[5] * x.z};
}

inline Sym3 embed(const Tensor2& t, const glm::vec3& u, const glm::vec3& v) {
    // T = ku u u^T + kuv (u v^T + v u^T) + kv v v^T
    auto entry = [&](int i, int j) { return t.ku * u[i] * u[j] + t.kuv * (u[i] * v[j] + v[i] * u[j]) + t.kv * v[i] * v[j]; };
    Sym3 r;
    r.m[0] = entry(0, 0), r.m[1] = entry(0, 1), r.m[2] = entry(0, 2);
    r.m[3] = entry(1, 1), r.m[4] = entry(1, 2), r.m[5] = entry(2, 2);
    return r;
}

inline Tensor2 restrict_to(const Sym3& t, const glm::vec3& u, const glm::vec3& v) {
    return {sym3_eval(t, u, u), sym3_eval(t, u, v), sym3_eval(t, v, v)};
}

// C contracted with x in its first slot: the symmetric matrix C(x, ., .).
inline Sym3 contract(const SymCubic3& t, const glm::vec3& x) {
    const float* c = t.c;  // index of (i, j, k) sorted: xxx0 xxy1 xxz2 xyy3 xyz4 xzz5 yyy6 yyz7 yzz8 zzz9
    Sym3 r;
    r.m[0] = c[0] * x.x + c[1] * x.y + c[2] * x.z;  // (x, x)
    r.m[1] = c[1] * x.x + c[3] * x.y + c[4] * x.z;  // (x, y)
    r.m[2] = c[2] * x.x + c[4] * x.y + c[5] * x.z;  // (x, z)
    r.m[3] = c[3] * x.x + c[6] * x.y + c[7] * x.z;  // (y, y)
    r.m[4] = c[4] * x.x + c[7] * x.y + c[8] * x.z;  // (y, z)
    r.m[5] = c[5] * x.x + c[8] * x.y + c[9] * x.z;  // (z, z)
    return r;
}

// C given as (C111, C112, C122, C222) in the frame (u, v).
inline SymCubic3 embed(const glm::vec4& C, const glm::vec3& u, const glm::vec3& v) {
    static constexpr int kIndex[10][3] = {{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 1, 1}, {0, 1, 2},
                                          {0, 2, 2}, {1, 1, 1}, {1, 1, 2}, {1, 2, 2}, {2, 2, 2}};
    SymCubic3 r;
    for (int n = 0; n < 10; ++n) {
        const int i = kIndex[n][0], j = kIndex[n][1], k = kIndex[n][2];
        r.c[n] = trilinear(C, u[i], v[i], u[j], v[j], u[k], v[k]);
    }
    return r;
}

inline glm::vec4 restrict_to(const SymCubic3& t, const glm::vec3& u, const glm::vec3& v) {
    const Sym3 cu = contract(t, u), cv = contract(t, v);
    return {sym3_eval(cu, u, u), sym3_eval(cu, u, v), sym3_eval(cu, v, v), sym3_eval(cv, v, v)};
}

inline void add_scaled(Sym3& acc, float w, const Sym3& t) {
    for (int i = 0; i < 6; ++i) acc.m[i] += w * t.m[i];
}

inline void add_scaled(SymCubic3& acc, float w, const SymCubic3& t) {
    for (int i = 0; i < 10; ++i) acc.c[i] += w * t.c[i];
}

}  // namespace kappa
