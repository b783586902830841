#include "render/fields/detail_fields.h"

#include "render/fields/detail_fields_job.h"

#include "geometry/scale/auto_smoothing.h"
#include "geometry/scale/denoise.h"
#include "geometry/scale/noise_level.h"
#include "geometry/scale/pixel_scale.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/surface_analysis.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace kappa::render {

namespace {

// Normals at scale s carry about sigma_noise / s of the noise's normal
// error: 25 times the noise level leaves a few degrees, too little to draw
// stray contour loops where the surface is seen edge-on.
constexpr float kContourNoise = 25.0f;

}  // namespace

namespace {

// Noisy meshes are drawn denoised: geometry/scale/denoise.h.

NoiseLevel set_floors(DetailSource& source, const Mesh& mesh, const SurfaceFields& raw, const VertexFaces& adjacency) {
    const NoiseLevel noise = estimate_noise_level(mesh, adjacency, raw.normals);
    source.noise_floor = choose_smoothing_widths(noise).normals;
    source.contour_floor = kContourNoise * noise.sigma;
    return noise;
}

}  // namespace

DetailSource make_detail_source(const Mesh& mesh, const SurfaceFields& raw, const VertexFaces* adjacency) {
    VertexFaces own;
    if (!adjacency) own = build_vertex_faces(mesh), adjacency = &own;
    DetailSource source;
    source.space = build_scale_space(mesh);
    const NoiseLevel noise = set_floors(source, mesh, raw, *adjacency);
    if (noise.relative >= kDenoiseNoise && source.noise_floor > 0 && !source.space.empty()) {
        source.denoised_at = source.noise_floor;
        denoise_at_floor(mesh, raw, *adjacency, source.noise_floor, source.space, source.denoised,
                         source.denoised_raw);
        set_floors(source, source.denoised, source.denoised_raw, *adjacency);
    }
    return source;
}

ViewScales view_scales(const Mesh& mesh, const DetailSource& source, const Camera& camera, int image_height,
                       float detail_px) {
    ViewScales v;
    v.sigma = pixel_sizes(mesh, camera.view, camera.fov_y_deg, image_height);
    // One pixel finer than the first level: the raw normals are the surface at pixel scale.
    v.fine = v.sigma;
    const float first_level = source.space.empty() ? 0.0f : source.space.level_scale(0);
    for (float& s : v.fine) s = std::max(s >= first_level ? s : 0.0f, source.contour_floor);
    for (float& s : v.sigma) s = std::max(s * detail_px, source.noise_floor);
    return v;
}

bool scales_need_raw_curvature(const DetailSource& source, const ViewScales& scales) {
    return source.raw != DetailSource::Raw::Inconsistent && uses_raw_estimate(source.space, scales.sigma);
}

bool needs_raw_curvature(const DetailSource& source, const ViewScales& scales) {
    return source.denoised_at == 0 && scales_need_raw_curvature(source, scales);
}

DetailFields detail_fields(const Mesh& mesh, DetailSource& source, const SurfaceFields& raw,
                           const ViewScales& scales) {
    DetailFieldsJob job(mesh, source, raw, scales);
    while (!job.done()) job.step();
    return job.take();
}

DetailFields detail_fields(const Mesh& mesh, DetailSource& source, const SurfaceFields& raw, const Camera& camera,
                           int image_height, float detail_px) {
    return detail_fields(mesh, source, raw, view_scales(mesh, source, camera, image_height, detail_px));
}

}  // namespace kappa::render
