// Two or four doubles at once for the per-face fits of the curvature job
// (GCC vector extensions: Doubles2 is one SSE2 register, Doubles4 one AVX
// register where the caller is compiled for AVX2, else two SSE2 ones). Code
// written once as a template on D = double, Doubles2 or Doubles4 runs the
// same IEEE operations in the same order in every lane (no FMA contraction:
// FMA is never enabled), so a face gets the same bits whether it is
// computed alone or in a group, on any of these paths, and so whatever the
// thread count and the processor.
#pragma once

#include "lanes.h"

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

// Vectors of four doubles are passed in two SSE registers on baseline x86-64;
// everything here is inlined, so no call between objects depends on it.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
// Lanes filled one by one (load3's z) look partly uninitialised to GCC (clang, web/, has no such warning).
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace kappa::lanes {

using Doubles2 = double __attribute__((vector_size(16)));
using Doubles4 = double __attribute__((vector_size(32)));
using Mask2 = int64_t __attribute__((vector_size(16)));  // comparison results: all bits set or none
using Mask4 = int64_t __attribute__((vector_size(32)));

// Lanes of D, and the type of D's comparisons.
template <typename D> constexpr int kLanes = sizeof(D) / sizeof(double);
template <typename D> struct MaskOf { using type = bool; };
template <> struct MaskOf<Doubles2> { using type = Mask2; };
template <> struct MaskOf<Doubles4> { using type = Mask4; };
template <typename D> using Mask = typename MaskOf<D>::type;

// The number type of one lane of T (T itself for float and double).
template <typename T> struct ScalarOf { using type = T; };
template <> struct ScalarOf<Doubles2> { using type = double; };
template <> struct ScalarOf<Doubles4> { using type = double; };
template <> struct ScalarOf<Lanes> { using type = float; };
template <typename T> using Scalar = typename ScalarOf<T>::type;

// a where m is set, else b (lane by lane for vectors: GCC's vector conditional).
template <typename D> KAPPA_LANES_INLINE D select(Mask<D> m, D a, D b) { return m ? a : b; }

// Square roots (correctly rounded, so the same bits in every lane type).
KAPPA_LANES_INLINE double root(double x) { return std::sqrt(x); }
#if defined(__x86_64__)
KAPPA_LANES_INLINE Doubles2 root(Doubles2 x) { return __builtin_ia32_sqrtpd(x); }
KAPPA_LANES_INLINE Doubles4 root(Doubles4 x) {  // two halves: AVX's sqrtpd needs the AVX target
    const Doubles2 lo = __builtin_ia32_sqrtpd(__builtin_shufflevector(x, x, 0, 1));
    const Doubles2 hi = __builtin_ia32_sqrtpd(__builtin_shufflevector(x, x, 2, 3));
    return __builtin_shufflevector(lo, hi, 0, 1, 2, 3);
}
#else
template <typename D> KAPPA_LANES_INLINE D root(D x) {
    D r = x;
    for (int j = 0; j < kLanes<D>; ++j) r[j] = std::sqrt(x[j]);
    return r;
}
#endif

// +1 or -1 with the sign bit of x (std::copysign(1, x)), also for float.
template <typename D> KAPPA_LANES_INLINE D sign_of(D x) {
    if constexpr (std::is_arithmetic_v<D>) {
        return std::copysign(D(1), x);
    } else {
        const Mask<D> sign_bit = Mask<D>(x) & int64_t(INT64_MIN);
        return D(Mask<D>(D{} + 1.0) | sign_bit);
    }
}

// Two doubles from and to memory (any alignment).
KAPPA_LANES_INLINE Doubles2 load_pair(const double* p) {
    Doubles2 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
KAPPA_LANES_INLINE void store_pair(double* p, Doubles2 v) { std::memcpy(p, &v, sizeof v); }

// A 3-vector of D.
template <typename D> struct Vec3 {
    D x, y, z;
};
template <typename D> KAPPA_LANES_INLINE Vec3<D> operator-(const Vec3<D>& a, const Vec3<D>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <typename D> KAPPA_LANES_INLINE Vec3<D> operator*(const Vec3<D>& a, D s) { return {a.x * s, a.y * s, a.z * s}; }
template <typename D> KAPPA_LANES_INLINE D dot(const Vec3<D>& a, const Vec3<D>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename D> KAPPA_LANES_INLINE Vec3<D> cross(const Vec3<D>& a, const Vec3<D>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename D> KAPPA_LANES_INLINE Vec3<D> normalize(const Vec3<D>& a) { return a * (1.0 / root(dot(a, a))); }

// Floats as many as D has lanes (float for one double), and their
// comparison results: what the face steps load and store, widened to D and
// narrowed back (exact one way, rounded to nearest the other, as a scalar
// conversion does).
using Floats2 = float __attribute__((vector_size(8)));
using Ints2 = int32_t __attribute__((vector_size(8)));
template <typename D> struct FloatsOf { using type = float; using mask = bool; };
template <> struct FloatsOf<Doubles2> { using type = Floats2; using mask = Ints2; };
template <> struct FloatsOf<Doubles4> { using type = Lanes; using mask = Ints4; };
template <typename D> using FloatsFor = typename FloatsOf<D>::type;
template <typename D> using FloatMask = typename FloatsOf<D>::mask;

template <typename D> KAPPA_LANES_INLINE D widen(FloatsFor<D> f) {
    if constexpr (std::is_same_v<D, double>) return f;
    else return __builtin_convertvector(f, D);
}
template <typename D> KAPPA_LANES_INLINE FloatsFor<D> narrow(D x) {
    if constexpr (std::is_same_v<D, double>) return float(x);
    else return __builtin_convertvector(x, FloatsFor<D>);
}
template <typename D> KAPPA_LANES_INLINE FloatMask<D> narrow_mask(Mask<D> m) {
    if constexpr (std::is_same_v<D, double>) return m;
    else return __builtin_convertvector(m, FloatMask<D>);
}
// f where m is set, else 0.
template <typename D> KAPPA_LANES_INLINE FloatsFor<D> keep(FloatMask<D> m, FloatsFor<D> f) {
    if constexpr (std::is_same_v<D, double>) return m ? f : 0.0f;
    else return FloatsFor<D>(FloatMask<D>(f) & m);
}

// Per lane, the two floats at get(lane) (a const float*), as two float
// lanes: one 8-byte load a lane, rearranged in registers.
template <typename D, typename Get> KAPPA_LANES_INLINE void load2(Get get, FloatsFor<D>& x, FloatsFor<D>& y) {
    constexpr int L = kLanes<D>;
    if constexpr (L == 1) {
        const float* p = get(0);
        x = p[0];
        y = p[1];
    } else {
        Floats2 xy[L];
        for (int j = 0; j < L; ++j) std::memcpy(&xy[j], get(j), sizeof(Floats2));
        if constexpr (L == 2) {
            x = __builtin_shufflevector(xy[0], xy[1], 0, 2);
            y = __builtin_shufflevector(xy[0], xy[1], 1, 3);
        } else {
            const Lanes lo = __builtin_shufflevector(xy[0], xy[1], 0, 2, 1, 3);  // x0 x1 y0 y1
            const Lanes hi = __builtin_shufflevector(xy[2], xy[3], 0, 2, 1, 3);  // x2 x3 y2 y3
            x = __builtin_shufflevector(lo, hi, 0, 1, 4, 5);
            y = __builtin_shufflevector(lo, hi, 2, 3, 6, 7);
        }
    }
}

// Per lane, the three floats at get(lane), as float lanes (x and y loaded
// together, then z).
template <typename D, typename Get> KAPPA_LANES_INLINE Vec3<FloatsFor<D>> load3(Get get) {
    constexpr int L = kLanes<D>;
    const float* p[L];
    for (int j = 0; j < L; ++j) p[j] = get(j);
    Vec3<FloatsFor<D>> r;
    load2<D>([&](int j) { return p[j]; }, r.x, r.y);
    if constexpr (L == 1) r.z = p[0][2];
    else for (int j = 0; j < L; ++j) r.z[j] = p[j][2];
    return r;
}
template <typename D> KAPPA_LANES_INLINE Vec3<D> widen3(const Vec3<FloatsFor<D>>& f) {
    return {widen<D>(f.x), widen<D>(f.y), widen<D>(f.z)};
}

// Writes four float lanes as four consecutive floats in each of L records
// 64 bytes apart: lane j at out + 64 j, v[0][j] to v[3][j] (a transposition
// in registers, then one store a record).
template <typename D> KAPPA_LANES_INLINE void store4(const FloatsFor<D> (&v)[4], void* out) {
    char* bytes = static_cast<char*>(out);
    constexpr int L = kLanes<D>;
    if constexpr (L == 1) {
        std::memcpy(bytes, v, 16);
    } else if constexpr (L == 2) {
        const Lanes r0 = {v[0][0], v[1][0], v[2][0], v[3][0]}, r1 = {v[0][1], v[1][1], v[2][1], v[3][1]};
        std::memcpy(bytes, &r0, 16);
        std::memcpy(bytes + 64, &r1, 16);
    } else {
        const Lanes t0 = __builtin_shufflevector(v[0], v[1], 0, 4, 1, 5);  // a0 b0 a1 b1
        const Lanes t1 = __builtin_shufflevector(v[0], v[1], 2, 6, 3, 7);  // a2 b2 a3 b3
        const Lanes t2 = __builtin_shufflevector(v[2], v[3], 0, 4, 1, 5);
        const Lanes t3 = __builtin_shufflevector(v[2], v[3], 2, 6, 3, 7);
        const Lanes r[4] = {__builtin_shufflevector(t0, t2, 0, 1, 4, 5), __builtin_shufflevector(t0, t2, 2, 3, 6, 7),
                            __builtin_shufflevector(t1, t3, 0, 1, 4, 5), __builtin_shufflevector(t1, t3, 2, 3, 6, 7)};
        for (int j = 0; j < 4; ++j) std::memcpy(bytes + 64 * j, &r[j], 16);
    }
}

// Writes three float lanes as L consecutive (x, y, z) triples (a
// glm::vec3 array): lane j at out + 3 j.
template <typename D> KAPPA_LANES_INLINE void store3(const Vec3<FloatsFor<D>>& v, float* out) {
    constexpr int L = kLanes<D>;
    if constexpr (L == 1) {
        out[0] = v.x;
        out[1] = v.y;
        out[2] = v.z;
    } else if constexpr (L == 2) {
        const Lanes r0 = {v.x[0], v.y[0], v.z[0], v.x[1]};
        const Floats2 r1 = {v.y[1], v.z[1]};
        std::memcpy(out, &r0, 16);
        std::memcpy(out + 4, &r1, 8);
    } else {
        const Lanes a = __builtin_shufflevector(v.x, v.y, 0, 4, 1, 5);  // x0 y0 x1 y1
        const Lanes c = __builtin_shufflevector(v.x, v.y, 2, 6, 3, 7);  // x2 y2 x3 y3
        const Lanes d = __builtin_shufflevector(a, v.z, 3, 5, 3, 5);    // y1 z1 y1 z1
        const Lanes r[3] = {__builtin_shufflevector(a, v.z, 0, 1, 4, 2),   // x0 y0 z0 x1
                            __builtin_shufflevector(d, c, 0, 1, 4, 5),     // y1 z1 x2 y2
                            __builtin_shufflevector(c, v.z, 6, 2, 3, 7)};  // z2 x3 y3 z3
        std::memcpy(out, r, 48);
    }
}

// Whether this processor runs AVX2, for the loops that have a version
// compiled for it (with Doubles4) besides the baseline one (Doubles2).
// allow_avx2(false) makes every loop take the baseline path (for tests).
inline std::atomic<bool>& avx2_allowed() {
    static std::atomic<bool> allowed{true};
    return allowed;
}
inline void allow_avx2(bool allowed) { avx2_allowed() = allowed; }
#if defined(__x86_64__)
#define KAPPA_TARGET_AVX2 __attribute__((target("avx2")))
inline bool has_avx2() {
    static const bool yes = __builtin_cpu_supports("avx2");
    return yes && avx2_allowed().load(std::memory_order_relaxed);
}
#else
#define KAPPA_TARGET_AVX2
inline bool has_avx2() { return false; }
#endif

template <typename D, typename Group>
KAPPA_LANES_INLINE void for_each_group_with(size_t first, size_t last, const Group& group) {
    size_t i = first;
    for (; i + kLanes<D> <= last; i += kLanes<D>) group(D{}, i);
    for (; i < last; ++i) group(0.0, i);
}

template <typename Group>
KAPPA_TARGET_AVX2 void for_each_group_avx2(size_t first, size_t last, const Group& group) {
    for_each_group_with<Doubles4>(first, last, group);
}

// Calls group(D{}, i) for i = first, first + L, ... with D the widest lanes
// this processor runs (Doubles4 with AVX2, else Doubles2) and L = kLanes<D>,
// then group(0.0, i) (one double) for the last indices one by one: group
// handles items i .. i + L - 1. Both paths give the same bits. Write group
// as a lambda marked KAPPA_LANES_LAMBDA so that it is compiled into each path.
template <typename Group>
void for_each_group(size_t first, size_t last, const Group& group) {
    if (has_avx2())
        for_each_group_avx2(first, last, group);
    else
        for_each_group_with<Doubles2>(first, last, group);
}
#define KAPPA_LANES_LAMBDA __attribute__((always_inline))

}  // namespace kappa::lanes

#pragma GCC diagnostic pop
