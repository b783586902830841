// Smoothing widths chosen from a mesh's noise level (noise_level.h): what
// `kappa curvature --smooth auto` and SmoothingOptions::automatic use.
//
// Rule, with h the median edge length, eta = sigma / h the relative noise
// and e = max(0, eta - 0.003):
//   f = (e / 0.02)^(1/4),
//   normals = 2.0 f h, curvature = 1.5 f h, dcurv = 3.0 f h.
// Why: curvature from normals smoothed with width s has a noise error of
// order sigma / s^2 and a bias of order (s k)^2, so the best s grows like
// sigma^(1/4); the constants are the measured optimum for a 2% noise on
// tori (20k vertices, R/r = 2.5 and 4), and they stay within a factor 2 of
// the optimum on random cubic height fields and ellipsoids for eta = 0.005
// to 0.2 (tests/test_geometry_auto_smoothing.cpp). The 0.003 floor is above
// what the estimator reads on clean tessellations (<= 0.0012), so clean
// meshes get exactly no smoothing; f is continuous in eta.
//
// Limitation: the rule knows the noise and the edge length, not the size of
// the features. On meshes whose features span only a few edges (a
// 642-vertex ellipsoid) with small noise (eta < 0.05) it smooths too much:
// there prefer explicit widths.
#pragma once

#include "geometry/scale/noise_level.h"
#include "geometry/surface_fields.h"

namespace kappa {

// Widths in model units for the given noise level; automatic is false in
// the result. All zero when noise.relative <= 0.003 or median_edge is 0.
SmoothingOptions choose_smoothing_widths(const NoiseLevel& noise);

}  // namespace kappa
