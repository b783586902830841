// The mesh's feature size fs: a length that says how big the mesh's
// features are, used to make thresholds dimensionless (a suggestive-contour
// threshold s is applied as Dw kr > s / fs^2, conventions.md).
//
// Definition: the median, over reliable vertices (no VertexFlag set), of the
// smaller radius of curvature 1 / max(|k1|, |k2|), clamped to
// [median edge length, bounding-sphere radius]. A sphere of radius R has
// fs = R; a torus with tube radius r has fs close to r. It scales with the
// model (fs of a mesh scaled by s is s fs) and does not depend on the
// tessellation of a smooth surface, unlike trimesh2's edge-length feature
// size. Noise on raw scans makes fs smaller, so thresholds get stricter
// there. Deterministic (no sampling).
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/surface_fields.h"

namespace kappa {

float feature_size(const Mesh& mesh, const SurfaceFields& fields);

}  // namespace kappa
