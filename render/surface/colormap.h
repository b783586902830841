// Robust ranges for the curvature colour maps (the colours themselves are
// in shaders/common/colormap.glsl). A range comes from a percentile of |value|
// over the reliable vertices, not from min/max, so one outlier (a noisy
// vertex at a hole) does not wash the whole map out.
#pragma once

#include "geometry/surface_fields.h"
#include "render/render_settings.h"

namespace kappa::render {

// The scalar a map shows at vertex i (the principal map: max(|k1|, |k2|),
// which sets its scale). Matches colormap_value() in colormap.glsl.
float colormap_scalar(ColorMap map, const SurfaceFields& fields, size_t i);

// Signed maps (k1, k2, mean, Gaussian, principal) are shown over
// [-range, range], |C| over [0, range]; range is the `percentile` of |value|
// over vertices without unreliable flags (all vertices if none is left).
// Returns 1 for ColorMap::None or an empty mesh, and never 0.
float robust_range(ColorMap map, const SurfaceFields& fields, float percentile = 0.98f);

}  // namespace kappa::render
