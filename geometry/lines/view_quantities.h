// Per-vertex view-dependent quantities on the CPU, for one eye position: the
// formulas of shaders/common/view_dependent.glsl and shaders/lines/lines_vert.glsl in the
// same float arithmetic, so CPU strokes and GPU lines cut triangles at the
// same points (conventions.md, "View-dependent quantities"):
//   v = unit vector from the vertex to the eye, (u, t) = (v.d1, v.d2)
//   kr sin^2(theta) = k1 u^2 + k2 t^2
//   Dw kr = C(w,w,w) - 2 tau^2 cot(theta), w = (u, t) / sin(theta),
//   tau = (k2 - k1) w1 w2 (DeCarlo et al. 2003; equal to C(w,w,w) + 2 K cot(theta) where kr = 0)
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/surface_fields.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace kappa {

struct ViewQuantities {
    std::vector<float> ndotv;          // n.v with the fields' normal (suggestive contours: front-facing)
    std::vector<float> contour_ndotv;  // n.v with the contour normal: occluding contours are its zeros
    std::vector<float> kr;             // kr sin^2(theta): suggestive contours are its zeros
    std::vector<float> sc_strength;    // Dw kr * fs^2: dimensionless, compared with --sc-threshold
};

// fields: with curvature (SurfaceFields::has_curvature); contour_normals: the
// normals whose n.v zeros are the occluding contours (empty: fields.normals;
// with --detail, the pixel-scale normals); feature_size: fs; only: empty, or
// one flag per vertex, non-zero where the quantities are needed (the others
// are left zero). Parallel over vertices; the same numbers for any thread count.
ViewQuantities compute_view_quantities(const Mesh& mesh, const SurfaceFields& fields,
                                       const std::vector<glm::vec3>& contour_normals, glm::vec3 eye,
                                       float feature_size, const std::vector<uint8_t>& only = {});
// The same into `out`, kept by a caller that computes them every frame: its
// arrays are resized, not cleared, so where `only` is zero they keep
// whatever they held.
void compute_view_quantities(const Mesh& mesh, const SurfaceFields& fields,
                             const std::vector<glm::vec3>& contour_normals, glm::vec3 eye, float feature_size,
                             const std::vector<uint8_t>& only, ViewQuantities& out);
// The same for the vertices [begin, end) alone, on the calling thread, into
// arrays already of one entry per vertex: for a caller that runs several
// per-vertex passes over one range while it is in cache.
void compute_view_quantities(const Mesh& mesh, const SurfaceFields& fields,
                             const std::vector<glm::vec3>& contour_normals, glm::vec3 eye, float feature_size,
                             const std::vector<uint8_t>& only, size_t begin, size_t end, ViewQuantities& out);

}  // namespace kappa
