// Denoising a scan for drawing and for choosing its view: the surface at the
// noise floor (scale_space.h's surface_at_scale, positions and all), reached
// in passes at the scale space's level 1.
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/surface_fields.h"
#include "scale_space.h"

#include <optional>

namespace kappa {

// Meshes are denoised from a noise level (noise_level.h, relative) of 8.5%
// of the edge length. The noise estimate cannot tell noise from true detail
// at the scale of the edges: dragon-50k (a decimated scan, rich in such
// detail) measures 7.0%, and denoised it lost the scallops of its back and
// drew broken suggestive contours; the bunny scan measures 2.5% and its
// drawing agrees best with bunny-1M's as it is (99% / 97.6%; denoised 97% /
// 93%). Synthetic normal noise of 0.1 edges measures 10%, and denoising
// brings its drawings from 89% to 95% on 82k faces.
constexpr float kDenoiseNoise = 0.085f;

// Denoising at the noise floor F runs in passes, each fitting on the
// normals of the last pass's cleaner surface, at the scale of the scale
// space's level 1 (3 mean edges: one level fitted a pass), as many as make
// the variances add up to about F^2 (one pass at F below 1.22 x 3 edges).
// Measured on bench_render_detail's irregular 82k-face shape with noise of
// 0.33 edges at 800 px, agreement with the clean drawing: one pass at F
// 78% / 79%, at F / 2 or 2F worse (53-65%); two passes at level 1 85% / 87%,
// as three at F / sqrt(3) (86% / 88%, twice the time); more passes no better.
//
// raw: the mesh's compute_surface_normals (or fields); space: its scale
// space, replaced by the denoised mesh's. Fills denoised (the mesh's faces,
// new positions) and denoised_raw (its compute_surface_normals). Needs
// noise_floor > 0 and a non-empty space.
void denoise_at_floor(const Mesh& mesh, const SurfaceFields& raw, const VertexFaces& adjacency, float noise_floor,
                      ScaleSpace& space, Mesh& denoised, SurfaceFields& denoised_raw);

// The mesh as the default view reads it (geometry/view/default_view.h): a
// mesh whose noise level is kDenoiseNoise or more denoised at its noise
// floor (choose_smoothing_widths' normals width); none for any other.
std::optional<Mesh> denoised_if_noisy(const Mesh& mesh);

}  // namespace kappa
