// Whether a mesh's raw per-vertex C (the paper's 1-ring estimate,
// Rusinkiewicz 2004 sec. 3.4) agrees with its scale space, so that fields
// finer than the scale space's first level may blend it in.
//
// The raw C is a difference of per-vertex curvature tensors across one
// ring: on a regular tessellation it is accurate, on an irregular one the
// tessellation dominates it. The accuracy lab's torus (200 x 100): uniform,
// raw |C| error 0.2%; vertices jittered by 0.3 cells, 118% raw against 14%
// at level 0 (1.5 mean edges) and 10% at 2 edges.
//
// Test (scale consistency): from the raw scale (half a mean edge) to level 0
// is 1.6 octaves, from level 0 to level 1 one more. Where the raw estimate
// resolves the surface, |C| = sqrt(a^2 + 3b^2 + 3c^2 + d^2) (frame-free)
// changes across the first step about as much per octave as across the
// second; tessellation error makes the first step far larger. Consistent:
// RMS over the reliable vertices of |C_raw| - |C_0| at most kRatio = 2
// times the RMS of |C_0| - |C_1|. Measured ratios: uniform torus 0.7,
// sphere-based models (regular 20k and 82k, irregular 82k faces) 0.8-1.3,
// dragon-50k 1.7; torus jittered by 0.1 cells 2.5, by 0.3 cells 10,
// bunny 4.1, fandisk 4.9, spot 33.
//
// Large meshes are sampled: every (V / 65536)-th vertex (deterministic).
// Cost: levels 0 and 1 are fitted (0.2 s more for bunny-1M zoomed in).
// Meshes with fewer than two levels (tiny) count as consistent.
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/scale/scale_space.h"
#include "geometry/surface_fields.h"

namespace kappa {

// The RMS differences of the test above (model units^-2).
struct RawConsistency {
    double raw_to_first = 0;     // RMS of |C_raw| - |C_0|
    double first_to_second = 0;  // RMS of |C_0| - |C_1|
    bool consistent = true;
};

// raw: compute_surface_fields(mesh) (with curvature). Fits levels 0 and 1
// of `space` if they are not yet. Deterministic.
RawConsistency raw_dcurv_consistency(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw);

// The same in steps (render/fields/detail_fields_job.h spreads it over a
// page's frames): whether the test applies (two levels, raw curvature), the
// scales at which it samples level 0 or 1 (zero at the vertices it skips),
// and its verdict from the fields at those scales (fields_at_scale, or
// fields_to_blend and blend_fields in pieces).
bool consistency_testable(const ScaleSpace& space, const SurfaceFields& raw);
std::vector<float> consistency_scales(const Mesh& mesh, const ScaleSpace& space, size_t level);
RawConsistency judge_consistency(const Mesh& mesh, const SurfaceFields& raw, const SurfaceFields& first,
                                 const SurfaceFields& second);

}  // namespace kappa
