// Four floats at once for the per-vertex passes of geometry/lines and the
// CPU depth raster (GCC vector extensions: SSE on x86-64, lane-wise code
// elsewhere); the operations every lane type shares (double_lanes.h adds
// vectors of doubles). Code written once as a
// template on F = float or F = Lanes runs the same IEEE operations in the same
// order either way, so a vertex gets the same bits whichever way it is
// computed (no FMA contraction: the build does not enable FMA).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

// Everything on lanes is inlined into its caller, so that a caller compiled
// for a wider instruction set (target("avx2")) runs it with that set.
#define KAPPA_LANES_INLINE [[gnu::always_inline]] inline

namespace kappa::lanes {

using Lanes = float __attribute__((vector_size(16)));
using Ints4 = int32_t __attribute__((vector_size(16)));  // also Lanes' comparison results

// Whether every lane of a comparison result is set.
inline bool all(Ints4 m) {
#ifdef __SSE__
    return __builtin_ia32_movmskps(Lanes(m)) == 15;
#else
    return (m[0] & m[1] & m[2] & m[3]) != 0;
#endif
}

inline float root(float x) { return std::sqrt(x); }
inline Lanes root(Lanes x) {
#ifdef __SSE__
    return __builtin_ia32_sqrtps(x);
#else
    return Lanes{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
#endif
}
// For float, double and their vectors (a vector condition picks lane by lane).
template <typename F> KAPPA_LANES_INLINE F larger(F a, F b) { return a < b ? b : a; }  // std::max's order
template <typename F> KAPPA_LANES_INLINE F magnitude(F x) { return x < 0.0f ? -x : x; }

// The integer nearest x, ties to even (the default rounding mode), for |x| < 2^31; lane by lane for Lanes
// (any value where x is not finite).
inline int32_t nearest(float x) { return int32_t(std::nearbyint(x)); }
inline Ints4 nearest(Lanes x) {
#ifdef __SSE2__
    return __builtin_ia32_cvtps2dq(x);
#else
    Ints4 out;
    for (int j = 0; j < 4; ++j) out[j] = std::isfinite(x[j]) ? nearest(x[j]) : 0;
    return out;
#endif
}

// Lane j of x (x itself for a float).
inline float lane(float x, int) { return x; }
inline float lane(Lanes x, int j) { return x[j]; }

// get(i), ..., get(i + 3) as lanes.
template <typename Get> Lanes gather(size_t i, Get get) { return Lanes{get(i), get(i + 1), get(i + 2), get(i + 3)}; }

}  // namespace kappa::lanes
