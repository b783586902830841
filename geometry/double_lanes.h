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
#include <type_traits>

// Vectors of four doubles are passed in two SSE registers on baseline x86-64;
// everything here is inlined, so no call between objects depends on it.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
// Lanes filled one by one (gather, gather3) look partly uninitialised to GCC.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

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

// a where m is set, else b (lane by lane for vectors: GCC's vector conditional).
template <typename D> KAPPA_LANES_INLINE D select(Mask<D> m, D a, D b) { return m ? a : b; }

template <typename D> KAPPA_LANES_INLINE D root(D x) {
    if constexpr (std::is_same_v<D, double>) {
        return std::sqrt(x);
    } else {
        D r = x;
        for (int j = 0; j < kLanes<D>; ++j) r[j] = std::sqrt(x[j]);
        return r;
    }
}

// +1 or -1 with the sign bit of x (std::copysign(1, x)), also for float.
template <typename D> KAPPA_LANES_INLINE D sign_of(D x) {
    if constexpr (std::is_arithmetic_v<D>) {
        return std::copysign(D(1), x);
    } else {
        const Mask<D> sign_bit = Mask<D>(x) & int64_t(INT64_MIN);
        return D(Mask<D>(D{} + 1.0) | sign_bit);
    }
}

// Lane j of x (x itself for a double), and whether lane j of a mask is set.
KAPPA_LANES_INLINE double lane(double x, int) { return x; }
KAPPA_LANES_INLINE bool lane(bool m, int) { return m; }
template <typename D, typename = std::enable_if_t<!std::is_arithmetic_v<D>>>
KAPPA_LANES_INLINE auto lane(D x, int j) { return x[j]; }

// get(0), ..., get(L - 1) as lanes.
template <typename D, typename Get> KAPPA_LANES_INLINE D gather(Get get) {
    if constexpr (std::is_same_v<D, double>) {
        return get(0);
    } else {
        D r{};
        for (int j = 0; j < kLanes<D>; ++j) r[j] = get(j);
        return r;
    }
}

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

// Per lane, the vec3 get(lane) (a glm::vec3 or dvec3) widened to double.
template <typename D, typename Get> KAPPA_LANES_INLINE Vec3<D> gather3(Get get) {
    if constexpr (std::is_same_v<D, double>) {
        const auto v = get(0);
        return {double(v.x), double(v.y), double(v.z)};
    } else {
        Vec3<D> r{};
        for (int j = 0; j < kLanes<D>; ++j) {
            const auto v = get(j);  // one load of the vector per lane
            r.x[j] = v.x;
            r.y[j] = v.y;
            r.z[j] = v.z;
        }
        return r;
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
