// Four floats at once for the per-vertex passes of geometry/lines (GCC vector
// extensions: SSE on x86-64, lane-wise code elsewhere). Code written once as a
// template on F = float or F = Lanes runs the same IEEE operations in the same
// order either way, so a vertex gets the same bits whichever way it is
// computed (no FMA contraction: the build does not enable FMA).
#pragma once

#include <cmath>
#include <cstddef>

namespace kappa::lanes {

using Lanes = float __attribute__((vector_size(16)));

inline float root(float x) { return std::sqrt(x); }
inline Lanes root(Lanes x) {
#ifdef __SSE__
    return __builtin_ia32_sqrtps(x);
#else
    return Lanes{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
#endif
}
template <typename F> F larger(F a, F b) { return a < b ? b : a; }  // std::max's order
template <typename F> F magnitude(F x) { return x < 0.0f ? -x : x; }

// Lane j of x (x itself for a float).
inline float lane(float x, int) { return x; }
inline float lane(Lanes x, int j) { return x[j]; }

// get(i), ..., get(i + 3) as lanes.
template <typename Get> Lanes gather(size_t i, Get get) { return Lanes{get(i), get(i + 1), get(i + 2), get(i + 3)}; }

}  // namespace kappa::lanes
