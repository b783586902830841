// Gaussian smoothing of per-vertex fields over the surface, as used for
// noisy scans in Rusinkiewicz 2004 (sec. 4) and trimesh2's diffuse_*.
// The value at vertex i becomes a weighted mean over the vertices j reached
// from i by a flood fill through the mesh while |p_j - p_i| < 3 sigma, with
//   w_ij = exp(-|p_j - p_i|^2 / (2 sigma^2)) * A_j * (n_i . n_j),
// A_j the vertex's Voronoi area; vertices facing away (n_i . n_j <= 0) are
// skipped, so thin sheets do not bleed into each other. Tensors are rotated
// into vertex i's frame before they are averaged. sigma <= 0 does nothing.
#pragma once

#include "curvature.h"

#include <glm/vec4.hpp>
#include <vector>

namespace kappa {

struct SmoothingContext {
    const Mesh& mesh;
    const VertexFaces& vf;
    const std::vector<float>& point_areas;
    const std::vector<glm::vec3>& normals;
};

void smooth_normals(const SmoothingContext& ctx, float sigma, std::vector<glm::vec3>& normals);

void smooth_curvature_tensors(const SmoothingContext& ctx, float sigma, VertexTensors& tensors);

// C in each vertex's (d1, d2) frame.
void smooth_dcurv(const SmoothingContext& ctx, float sigma, const std::vector<glm::vec3>& d1,
                  const std::vector<glm::vec3>& d2, std::vector<glm::vec4>& dcurv);

}  // namespace kappa
