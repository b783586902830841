#include "denoise.h"

#include "auto_smoothing.h"
#include "noise_level.h"
#include "geometry/surface_analysis.h"

#include <algorithm>
#include <cmath>

namespace kappa {

// Level 1 of the scale space: one level fitted a pass (denoise.h).
constexpr int kDenoiseLevel = 1;

void denoise_at_floor(const Mesh& mesh, const SurfaceFields& raw, const VertexFaces& adjacency, float noise_floor,
                      ScaleSpace& space, Mesh& denoised, SurfaceFields& denoised_raw) {
    denoised.faces = mesh.faces;
    const float level = space.level_scale(kDenoiseLevel);
    const float variances = noise_floor * noise_floor / (level * level);
    const int passes = std::max(1, int(std::lround(variances)));
    const std::vector<float> sigma(mesh.vertex_count(), passes == 1 ? noise_floor : level);
    for (int pass = 0; pass < passes; ++pass) {
        const bool first = pass == 0;
        denoised.positions =
            surface_at_scale(first ? mesh : denoised, space, first ? raw : denoised_raw, sigma).positions;
        denoised_raw = compute_surface_normals(denoised, nullptr, &adjacency);
        space = build_scale_space(denoised);
    }
}

std::optional<Mesh> denoised_if_noisy(const Mesh& mesh) {
    const VertexFaces adjacency = build_vertex_faces(mesh);
    const SurfaceFields raw = compute_surface_normals(mesh, nullptr, &adjacency);
    const NoiseLevel noise = estimate_noise_level(mesh, adjacency, raw.normals);
    const float floor = choose_smoothing_widths(noise).normals;
    ScaleSpace space = build_scale_space(mesh);
    if (!(noise.relative >= kDenoiseNoise) || !(floor > 0) || space.empty()) return std::nullopt;
    Mesh denoised;
    SurfaceFields denoised_raw;
    denoise_at_floor(mesh, raw, adjacency, floor, space, denoised, denoised_raw);
    return denoised;
}

}  // namespace kappa
