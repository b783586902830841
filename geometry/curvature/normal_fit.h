// `--estimator normal-fit`: the "fit to normal curvatures" of Rusinkiewicz
// 2004, sec. 2: along each edge from vertex p to a neighbour q, the normal
// curvature of the circle through p and q with normal n at p,
//   k_e = 2 n . (p - q) / |p - q|^2           (the paper's eq. 3),
// and II = [[e, f], [f, g]] in the tangent frame of the Max normal n is
// fitted by least squares to II(s, s) = k_e (the paper's eq. 1), s the
// edge direction projected into the tangent plane (cf. Meyer et al. 2002,
// Taubin 1995). Exact on spheres with exact normals.
//
// Inputs: mesh, vertex-vertex adjacency (the 1-ring), Max normals. Output:
// II only; C comes from the paper's C step (estimate.h). Boundary vertices
// use their one-sided ring; fewer than three independent directions give
// a zero tensor and kFlagFallback.
#pragma once

#include "estimate.h"

namespace kappa {

CurvatureEstimate estimate_normal_fit(const EstimatorInput& in);

}  // namespace kappa
