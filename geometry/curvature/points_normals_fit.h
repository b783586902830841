// `--estimator points-normals-fit`: the cubic fit of Goldfeather &
// Interrante 2004 ("A novel cubic-order algorithm for approximating
// principal direction vectors", ACM TOG 23(1), sec. 4), as compared in
// Rusinkiewicz 2004, sec. 2. In the frame of the vertex's Max normal, with
// the vertex at the origin, the height function
//   z = A/2 x^2 + B x y + C/2 y^2 + D x^3 + E x^2 y + F x y^2 + G y^3
// is fitted by least squares to the 1-ring's positions (z_i at (x_i, y_i))
// and normals (-a_i/c_i = z_x, -b_i/c_i = z_y for a neighbour normal
// (a_i, b_i, c_i)): three equations per neighbour, coordinates scaled by
// the ring's radius so that both kinds weigh alike. II = -[[A, B], [B, C]]
// (II = dN, convex positive) and C = -(6D, 2E, 2F, 6G): the fit gives C
// natively (graph_geometry.h with zero gradient).
//
// Inputs: mesh, vertex-vertex adjacency (the 1-ring), Max normals (frame
// and data). Output: II and C. Too few independent equations for the
// cubic (fewer than three neighbours, or degenerate) drop to the quadratic
// A, B, C (C = 0) and set kFlagFallback; if that fails too, zero.
#pragma once

#include "estimate.h"

namespace kappa {

CurvatureEstimate estimate_points_normals_fit(const EstimatorInput& in);

}  // namespace kappa
