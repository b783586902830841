#include "render/detail_fields.h"

#include "geometry/feature_size.h"
#include "geometry/scale/auto_smoothing.h"
#include "geometry/scale/noise_level.h"
#include "geometry/scale/pixel_scale.h"
#include "geometry/vertex_faces.h"

#include <algorithm>

namespace kappa::render {

namespace {

// Normals at scale s carry about sigma_noise / s of the noise's normal
// error: 25 times the noise level leaves a few degrees, too little to draw
// stray contour loops where the surface is seen edge-on.
constexpr float kContourNoise = 25.0f;

}  // namespace

DetailSource make_detail_source(const Mesh& mesh, const SurfaceFields& raw) {
    DetailSource source;
    source.space = build_scale_space(mesh);
    const NoiseLevel noise = estimate_noise_level(mesh, build_vertex_faces(mesh), raw.normals);
    source.noise_floor = choose_smoothing_widths(noise).normals;
    source.contour_floor = kContourNoise * noise.sigma;
    return source;
}

DetailFields detail_fields(const Mesh& mesh, DetailSource& source, const SurfaceFields& raw, const Camera& camera,
                           int image_height, float detail_px) {
    DetailFields out;
    std::vector<float> sigma = pixel_sizes(mesh, camera.view, camera.fov_y_deg, image_height);
    // One pixel finer than the first level: the raw normals are the surface at pixel scale.
    std::vector<float> fine = sigma;
    const float first_level = source.space.empty() ? 0.0f : source.space.level_scale(0);
    for (float& s : fine) s = std::max(s >= first_level ? s : 0.0f, source.contour_floor);
    out.fine_normals = normals_at_scale(mesh, source.space, raw, fine);
    for (float& s : sigma) s = std::max(s * detail_px, source.noise_floor);
    out.fields = fields_at_scale(mesh, source.space, raw, sigma);
    out.feature_size = feature_size(mesh, out.fields);
    return out;
}

}  // namespace kappa::render
