// kappa's scale space: normals, curvature and its derivative C at a range of
// surface scales, and per-vertex fields at any scale in between.
//
// The paper's estimator (Rusinkiewicz 2004) is right at one scale, the
// mesh's own: on a noisy scan or a mesh much finer than a pixel it draws
// scribbles. Following the idea of Ni et al. 2006 ("Multi-scale line
// drawings from 3D meshes": precompute fields at several scales, pick one
// per vertex from its projected pixel size), each level of a cluster
// of clusters (surface_clusters.h: pieces of the mesh in grid cells whose
// size doubles from level to level) gets its own fields, estimated on the
// clusters as the paper does on faces but over a Gaussian neighbourhood:
//   1. normal: the clusters' area-weighted mean normals, averaged with
//      weights A_Q (1 - d^2 / R^2)^2 over the clusters Q within R = 2.5
//      sigma (reached through cluster adjacency, facing the same way): a
//      bump close to a Gaussian of width sigma;
//   2. curvature: the weighted least-squares fit of II from normal
//      differences along centroid differences, II e = dn (paper eq. 3,
//      with neighbours in place of a face's edges);
//   3. C: the same fit of C from curvature differences, C(e) = dII
//      (paper sec. 3.4).
// sigma is the level's cell size; level k has twice the scale of level
// k - 1. The raw per-vertex estimate counts as the scale raw_scale (half a
// mean edge). fields_at_scale() blends, per vertex, the two levels around
// the wanted sigma (linearly in log sigma): each level's value at a vertex
// is the bump-weighted mean of its cluster and the adjacent ones, with
// tensors summed as tensors of 3D space (tensor3.h) and restricted to the
// vertex's blended tangent plane.
#pragma once

#include "surface_clusters.h"
#include "geometry/mesh.h"
#include "geometry/surface_fields.h"
#include "geometry/tensor_frames.h"
#include "tensor3.h"

#include <glm/vec4.hpp>

#include <cmath>
#include <vector>

namespace kappa {

struct ScaleLevelFields {
    std::vector<glm::vec3> normal;  // unit
    std::vector<Sym3> curvature;    // II as a tensor of 3D space (tensor3.h)
    std::vector<SymCubic3> dcurv;   // C as a tensor of 3D space
    std::vector<uint8_t> valid;     // 0 where the cluster had too little around it for a fit
    // The same, packed per cluster for the per-vertex blend: where (centroid,
    // and area or 0 where not valid) and what.
    struct Value {
        glm::vec3 normal;
        Sym3 curvature;
        SymCubic3 dcurv;
    };
    std::vector<glm::vec4> place;
    std::vector<Value> value;

    bool fitted() const { return !valid.empty(); }
};

// Levels are clustered and fitted when first needed: a drawing at one scale
// pays for the one or two levels it blends.
struct ScaleSpace {
    float raw_scale = 0;    // the scale the raw per-vertex estimate stands for
    float first_cell = 0;   // cell of level 0; level l has first_cell * 2^l
    glm::vec3 origin{0};    // where the grids' cells are aligned
    std::vector<ClusterLevel> clusters;    // one per level (built on demand)
    std::vector<ScaleLevelFields> levels;  // one per level (fitted on demand)

    bool empty() const { return levels.empty(); }
    float level_scale(size_t level) const { return std::ldexp(first_cell, int(level)); }
    // Largest scale available (raw_scale when there are no levels).
    float max_scale() const { return empty() ? raw_scale : level_scale(levels.size() - 1); }
};

// Sets up the levels (first cell 1.5 mean edge lengths, doubling up to a
// quarter of the bounding radius), none built yet: cheap.
ScaleSpace build_scale_space(const Mesh& mesh);

// Whether fields at these scales blend in the raw per-vertex estimate (some
// sigma below the first level's). When not, fields_at_scale needs only the
// raw normals, areas and flags (compute_surface_normals); without raw
// curvature it takes it as zero where it would have used it.
bool uses_raw_estimate(const ScaleSpace& space, const std::vector<float>& sigma);

// Builds and fits every level. raw: compute_surface_fields' output for the
// mesh (its normals and areas seed the clusters).
void fit_all_levels(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw);

// Per-vertex fields at scale sigma[v] (model units), fitting the levels
// they need first. sigma[v] <= raw_scale gives the raw fields exactly;
// flagged vertices always keep their raw values. Deterministic for any
// thread count.
SurfaceFields fields_at_scale(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw,
                              const std::vector<float>& sigma);

// Only the normals of fields_at_scale (cheaper).
std::vector<glm::vec3> normals_at_scale(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw,
                                        const std::vector<float>& sigma);

// The same with one sigma for every vertex.
SurfaceFields fields_at_scale(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw, float sigma);

}  // namespace kappa
