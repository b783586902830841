// One call that computes every per-vertex field of SurfaceFields for a mesh:
// normals (Max 1999), mixed Voronoi areas (Meyer et al. 2002), curvature and
// its derivative (Rusinkiewicz 2004), with optional Gaussian smoothing.
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"
#include "surface_fields.h"

#include <functional>

namespace kappa {

// Wall-clock seconds spent in each stage: areas is the face geometry
// (face_geometry.h), normals the per-vertex pass that also sums the point
// areas and sets the flags (vertex_basics.h).
struct StageTimes {
    double adjacency = 0, normals = 0, areas = 0, curvature = 0, dcurv = 0, smoothing = 0;
    double total() const { return adjacency + normals + areas + curvature + dcurv + smoothing; }
};

// progress(fraction in [0,1], stage name); may be empty. Called from the
// calling thread only.
using ProgressFn = std::function<void(float, const char*)>;

// With smoothing.automatic, the noise level is estimated from the raw
// normals (scale/noise_level.h) and every width left at 0 is chosen from it
// (scale/auto_smoothing.h); explicit widths are kept. The widths used and
// the noise estimate are in the result's `smoothing` and `noise`.
//
// adjacency: the mesh's vertex-face rows (geometry/mesh/vertex_faces.h) when
// the caller has them already (drawing builds them once for the creases, the
// fields and the scale space); null: built here (timed as `adjacency`).
SurfaceFields compute_surface_fields(const Mesh& mesh, const SmoothingOptions& smoothing = {},
                                     StageTimes* times = nullptr, const ProgressFn& progress = {},
                                     const VertexFaces* adjacency = nullptr);

// Only the first stages: normals, point areas and flags (k1, k2, d1, d2 and
// dcurv left empty). What the scale space needs when a drawing's scales are
// all above the raw estimate's (render/fields/detail_fields.h).
SurfaceFields compute_surface_normals(const Mesh& mesh, StageTimes* times = nullptr,
                                      const VertexFaces* adjacency = nullptr);

}  // namespace kappa
