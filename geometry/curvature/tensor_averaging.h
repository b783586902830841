// `--estimator tensor-averaging`: the curvature tensor of Cohen-Steiner &
// Morvan 2003 ("Restricted Delaunay triangulations and normal cycle",
// SoCG), averaged over the 1-ring as Alliez et al. 2003 ("Anisotropic
// polygonal remeshing", SIGGRAPH, sec. 3.1) use it:
//   T = 1/|B| sum over edges e of beta(e) |e n B| e e^T,
// B the 1-ring (its faces), beta(e) the signed angle between the normals of
// the two faces at e (convex positive), e the unit edge direction. Spokes
// (edges at the vertex) lie inside B; rim edges (opposite the vertex) on its
// border count half their length. An edge with a bend beta across it bends
// the surface across its direction, so II is T turned by 90 degrees in the
// tangent plane of the vertex's Max normal: II_uu = T_vv, II_vv = T_uu,
// II_uv = -T_uv.
//
// Inputs: mesh, vertex faces, face area normals, Max normals. Output: II
// only; C comes from the paper's C step (estimate.h). Edges with fewer or
// more than two faces add nothing (boundary and non-manifold vertices are
// flagged by the pipeline); a vertex whose 1-ring has no area gets a zero
// tensor and kFlagFallback.
#pragma once

#include "estimate.h"

namespace kappa {

CurvatureEstimate estimate_tensor_averaging(const EstimatorInput& in);

}  // namespace kappa
