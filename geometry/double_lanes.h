// Four doubles at once for the per-face fits of the curvature job (GCC
// vector extensions: two SSE2 operations each on baseline x86-64, one AVX
// operation where a caller is compiled for it). Code written once as a
// template on D = double or D = Doubles runs the same IEEE operations in the
// same order either way (no FMA contraction: the build does not enable FMA),
// so a face gets the same bits whether it is computed alone or in a group of
// four, and so whatever the thread count.
#pragma once

#include <cmath>
#include <cstdint>

// Vectors of four doubles are passed in two SSE registers on baseline x86-64;
// every function here is inline, so no call between objects depends on it.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace kappa::lanes {

using Doubles = double __attribute__((vector_size(16)));
using DoubleMask = int64_t __attribute__((vector_size(16)));  // comparison results: all bits set or none
constexpr int kDoubleLanes = sizeof(Doubles) / sizeof(double);

// The mask type of D's comparisons.
template <typename D> struct MaskOf { using type = bool; };
template <> struct MaskOf<Doubles> { using type = DoubleMask; };
template <typename D> using Mask = typename MaskOf<D>::type;

inline double select(bool m, double a, double b) { return m ? a : b; }
inline Doubles select(DoubleMask m, Doubles a, Doubles b) { return m ? a : b; }

inline double root(double x) { return std::sqrt(x); }
template <typename D> D larger(D a, D b) { return select(a < b, b, a); }
template <typename D> D magnitude(D x) { return select(x < 0.0, -x, x); }
inline Doubles root(Doubles x) { return __builtin_ia32_sqrtpd(x); }

// +1 or -1 with the sign bit of x (std::copysign(1.0, x)).
inline double sign_of(double x) { return std::copysign(1.0, x); }
inline Doubles sign_of(Doubles x) {
    const DoubleMask sign_bit = DoubleMask(x) & int64_t(INT64_MIN);
    return Doubles(DoubleMask(Doubles{1, 1}) | sign_bit);
}

// Lane j of x (x itself for a double), and whether lane j of a mask is set.
inline double lane(double x, int) { return x; }
inline double lane(Doubles x, int j) { return x[j]; }
inline bool lane(bool m, int) { return m; }
inline bool lane(DoubleMask m, int j) { return m[j] != 0; }

// get(0), ..., get(3) as lanes; get(0) for a double.
template <typename D, typename Get> D gather(Get get) {
    if constexpr (sizeof(D) == sizeof(double))
        return get(0);
    else
        return Doubles{get(0), get(1)};
}

// A 3-vector of D.
template <typename D> struct Vec3 {
    D x, y, z;
};
template <typename D> Vec3<D> operator-(const Vec3<D>& a, const Vec3<D>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <typename D> Vec3<D> operator*(const Vec3<D>& a, D s) { return {a.x * s, a.y * s, a.z * s}; }
template <typename D> D dot(const Vec3<D>& a, const Vec3<D>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <typename D> Vec3<D> cross(const Vec3<D>& a, const Vec3<D>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename D> Vec3<D> normalize(const Vec3<D>& a) { return a * (1.0 / root(dot(a, a))); }

// Per lane, the vec3 get(lane) (a glm::vec3 or dvec3) widened to double.
template <typename D, typename Get> Vec3<D> gather3(Get get) {
    return {gather<D>([&](int j) { return double(get(j).x); }), gather<D>([&](int j) { return double(get(j).y); }),
            gather<D>([&](int j) { return double(get(j).z); })};
}

}  // namespace kappa::lanes

#pragma GCC diagnostic pop
