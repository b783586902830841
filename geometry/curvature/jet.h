// `--estimator jet`: osculating jets (Cazals & Pouget 2003, "Estimating
// differential quantities using polynomial fitting of osculating jets",
// SGP; CGAL's Monge_via_jet_fitting).
//
// Per vertex: the vertex's k-ring in the frame of its Max normal, centred on
// the vertex and scaled to unit radius; a height polynomial z = sum c_ij x^i
// y^j of degree 4 or 5 (15 or 21 coefficients, constant term included: the
// jet approximates, it does not interpolate) fitted by least squares
// (normal_equations.h: equilibrated Cholesky in double, A^T A formed from
// moments). The normal, II and C are read off the polynomial at the origin
// exactly, gradient included (graph_geometry.h), instead of by Cazals &
// Pouget's change to Monge coordinates: the same quantities. Where the jet's
// normal is more than 5 degrees from the frame's axis (a poor vertex normal)
// the fit is repeated in the jet normal's frame.
//
// Ring vertices whose Max normal is more than 60 degrees from the vertex's (a
// ring that wraps round a thin part) are left out of the fit. Limitation: on
// noisy scans, features narrower than the noise-adapted ring (the bunny's
// ear rims) still give outliers, up to ten times the paper's 1-ring value.
//
// Inputs: the mesh, its vertex faces and the Max normals (they give the
// fitting frame and the side test only). Outputs (estimate.h): the jet's normal, II and C per
// vertex, all three native.
//
// Degree and rings (JetOptions 0 = automatic) follow the mesh's noise level
// eta relative to the median edge (scale/noise_level.h, itself a cubic-jet
// residual), jet_plan_for_noise: clean (eta < 0.03%): degree 5 on the 3-ring;
// eta < 0.2%: degree 4 on the 3-ring; < 1%: degree 4 on the 4-ring; else
// degree 4 on the 5-ring. The error is truncation (a degree-n jet: curvature
// O(h^(n-1)), C O(h^(n-2)); Cazals & Pouget 2003, Th. 3) plus noise
// amplification, which falls fast with the ring. Measured on an irregular
// 20k-vertex torus (R 1, r 0.4; tests/test_geometry_estimators.cpp and the
// accuracy lab): clean curvature error 0.021% (degree 4, 2-ring), 0.0088%
// (degree 5, 3-ring), 0.029% (degree 4, 3-ring), 0.049% (4-ring), 0.094%
// (5-ring); per unit eta of noise 77, 22, 18, 8.6, 4.7. The thresholds are
// near where the sums cross, kept clear of the noise estimate's floor on
// clean meshes (about 1e-4).
//
// On clean meshes the other limit is the positions' float rounding (about
// 6e-8 of the coordinates): where a fit's RMS residual is no larger than
// rounding alone leaves (flat regions, fine tessellations) the ring grows by
// one and the vertex is fitted again, which averages rounding down
// (automatic rings only). Measured (accuracy lab meshes): cubic patches
// 0.0046% / 0.43% (curvature / C) -> 0.0018% / 0.14%; the tori unchanged.
//
// The 2-ring competes (automatic rings, degree 5 only): on uniform meshes a
// degree-4 jet on the 2-ring (CGAL's configuration) has 5 times less
// truncation error than degree 5 on the 3-ring (odd terms cancel on
// symmetric rings; both then go as the fourth power of the radius), on
// irregular ones the 3-ring's degree 5 wins, and where rounding rules the
// wider ring does. Per vertex, three candidates from one pass over the ring
// (moments of the 2-ring prefix kept): degree 4 and degree 5 on the whole
// ring, and degree 4 on the 2-ring with the degree-5 fit's fifth-order
// terms subtracted from the heights. The whole ring's fit is degree 4 unless
// an F test finds the fifth-order terms significant; it is then weighed
// against the 2-ring's by a plug-in rule (Lepski's principle, jet.cpp
// choose_terms): the 2-ring's terms where their difference exceeds what the
// noise (rounding, or the mesh's noise from a 4096-vertex sample of 2-ring
// and whole-ring residuals, which also decides the plan in place of the
// cubic noise level where smaller: that one reads a coarse clean mesh's
// truncation as noise) explains; separately for the curvature terms and for
// C. Measured against CGAL's jet (accuracy lab, bench/cgal_jet_estimate.h;
// curvature, C): unit icosphere 10k vertices 0.68, 0.61 of CGAL's error;
// uniform torus 200 x 100 0.87, 0.23; 100 x 50 0.24, 0.25; irregular torus,
// random ellipsoid and cubic patches 0.1 to 0.6. Limitation: meshes so
// coarse that even these residuals read as noise (a 162-vertex icosphere, a
// torus of 50 x 25) keep the noisy plan, 2.8 to 5.7 times CGAL's
// curvature error (8 to 11 before).
//
// Cost: the fits share their work. One Cholesky factor of the whole ring's
// degree-5 normal equations gives the degree-4 fit too (its leading block),
// every residual (normal_equations.h, NestedFits) and the variance factors
// of both; the 2-ring's factor serves its two right-hand sides; the
// sampled vertices' fits are the plan's own where it is the clean one; the
// cubic noise level is computed only where the sample reads noisy, and a
// first look at an eighth of the sample settles clearly noisy meshes.
//
// Where the neighbourhood is too small for the degree (fewer than unknowns +
// 3 points: boundaries, small components) it is grown by one ring, up to
// `max_rings`; if that is not enough, or the points are degenerate (the
// equilibrated normal equations are singular), the degree drops, down to 2
// (C = 0) and then to a zero estimate. A degree below 4 (or below the one
// asked for, if lower) and the zero estimate set kFlagFallback. Isolated
// vertices get the zero estimate and the flag.
//
// Each vertex is computed independently by one thread: results do not
// depend on the thread count.
#pragma once

#include "estimate.h"

namespace kappa {

struct JetOptions {
    int degree = 0;      // 2 to 5; 0: from the noise level
    int rings = 0;       // neighbourhood size before any growth; 0: from the noise level
    int max_rings = 4;   // growth limit for small neighbourhoods
    bool refit = true;   // fit again in the jet normal's frame when it is more than 5 degrees off
};

CurvatureEstimate estimate_jet(const EstimatorInput& in, const JetOptions& options = {});

struct JetPlan {
    int degree, rings;
};
// Degree and rings for a relative noise level (above).
JetPlan jet_plan_for_noise(float relative_noise);

}  // namespace kappa
