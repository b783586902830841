// `--estimator jet`: osculating jets (Cazals & Pouget 2003, "Estimating
// differential quantities using polynomial fitting of osculating jets",
// SGP; CGAL's Monge_via_jet_fitting).
//
// Per vertex: the vertex's k-ring (2-ring by default) in the frame of its
// Max normal, centred on the vertex and scaled to unit radius; a degree-4
// height polynomial z = sum c_ij x^i y^j (15 coefficients, constant term
// included: the jet approximates, it does not interpolate) fitted by least
// squares (normal_equations.h: equilibrated Cholesky in double). The
// normal, II and C are then read off the polynomial at the origin exactly,
// gradient included (graph_geometry.h), instead of by Cazals & Pouget's
// change to Monge coordinates: the same quantities.
//
// Inputs: the mesh, its vertex-vertex adjacency and the Max normals (they
// give the fitting frame only). Outputs (estimate.h): the jet's normal, II
// and C per vertex, all three native.
//
// Where the neighbourhood is too small for a degree-4 fit (fewer than 18
// points: boundaries, small components) it is grown by one ring, up to
// `max_rings`; if that is not enough, or the points are degenerate (the
// equilibrated normal equations are singular), the degree drops to 3, then
// 2 (C = 0), then to a zero estimate, and the vertex gets kFlagFallback.
// Isolated vertices get the zero estimate and the flag.
//
// Noise: the jet's error is truncation (clean meshes: O(h^3) for curvature,
// O(h^2) for C, smallest on the 2-ring) plus noise amplification (largest on
// the 2-ring: 15 unknowns from about 19 points). With `rings` = 0 (the
// default) the ring count follows the mesh's noise level eta, relative to
// the median edge (scale/noise_level.h, itself a cubic-jet residual):
// 2 rings below eta = 0.03%, 3 below 0.2%, 4 below 1%, else 5. Measured on
// a torus (R 1, r 0.4, 20k vertices, irregular), curvature error per unit
// eta: 77 (2 rings), 20 (3), 8.6 (4), 4.7 (5), against clean errors of
// 0.019%, 0.026%, 0.049%, 0.094%: the thresholds are where the sums cross,
// moved up to stay clear of the estimator's floor on clean meshes.
//
// Each vertex is computed independently by one thread: results do not
// depend on the thread count.
#pragma once

#include "estimate.h"

namespace kappa {

struct JetOptions {
    int degree = 4;      // 2, 3 or 4
    int rings = 0;       // neighbourhood size before any growth; 0: from the noise level
    int max_rings = 4;   // growth limit for small neighbourhoods
    bool refit = true;   // fit again in the jet normal's frame when it is more than 5 degrees off
};

CurvatureEstimate estimate_jet(const EstimatorInput& in, const JetOptions& options = {});

// The ring count for a relative noise level (above).
int jet_rings_for_noise(float relative_noise);

}  // namespace kappa
