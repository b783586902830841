// kappa's scale space: normals, curvature and its derivative C at a range of
// surface scales, and per-vertex fields at any scale in between.
//
// The paper's estimator (Rusinkiewicz 2004) is right at one scale, the
// mesh's own: on a noisy scan or a mesh much finer than a pixel it draws
// scribbles. Following the idea of Ni et al. 2006 ("Multi-scale line
// drawings from 3D meshes": precompute fields at several scales, pick one
// per vertex from its projected pixel size), level l cuts the mesh into
// clusters of grid cells of size sigma_l = 1.5 mean edges x 2^l
// (surface_clusters.h) and fits normals, II and C on them (level_fit.h).
// The raw per-vertex estimate counts as the scale raw_scale (half a mean
// edge). fields_at_scale() blends, per vertex, the two estimates around the
// wanted sigma, linearly in log sigma. A level's value at a vertex is the
// kernel-weighted mean (scale_kernel, R = 1.25 cells) of the vertex's
// cluster and the adjacent ones, each carried from its centroid to the
// vertex to first order (n + II dp, II + C(dp)); tensors are summed as
// tensors of 3D space (tensor3.h) and restricted to the vertex's blended
// tangent plane, then diagonalised.
//
// Boundaries: clusters at an open boundary fit from their one-sided
// neighbourhood. Flagged vertices (isolated, degenerate) keep their raw
// values; a vertex whose clusters have no valid fit (tiny components) takes
// the raw estimate for that level.
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/surface_fields.h"
#include "level_fit.h"
#include "level_value_cache.h"
#include "surface_clusters.h"

#include <glm/vec4.hpp>

#include <cmath>
#include <memory>
#include <vector>

namespace kappa {

// Levels are clustered and fitted when first needed: a drawing at one scale
// pays for the one or two levels it blends.
struct ScaleSpace {
    float raw_scale = 0;    // the scale the raw per-vertex estimate stands for
    float first_cell = 0;   // cell of level 0; level l has first_cell * 2^l
    glm::vec3 origin{0};    // where the grids' cells are aligned
    std::vector<ClusterLevel> clusters;    // one per level (built on demand)
    std::vector<ScaleLevelFields> levels;  // one per level (fitted on demand)
    // Each level's value at each vertex, the curvature blend's and the surface's, kept when
    // enabled (level_value_cache.h): caches, filled by the blends that read the space.
    // The surface's values are 33 bytes a vertex, the curvature's 81: a third of the budget.
    mutable LevelValueCache tensor_values{20, LevelValueCache::curvature_budget_bytes()},
        surface_values{8, LevelValueCache::curvature_budget_bytes() / 3};
    void keep_level_values(bool on) { tensor_values.enable(on), surface_values.enable(on); }
    // The vertices cluster by cluster of the finest level built (clusters run along a Z-order
    // curve: surface_clusters.h): the order in which the blends visit them, so that each
    // neighbourhood of clusters they read is in the cache. Any order gives the same values.
    std::vector<uint32_t> visit_order;
    size_t visit_order_level = SIZE_MAX;  // the level it follows

    bool empty() const { return levels.empty(); }
    float level_scale(size_t level) const { return std::ldexp(first_cell, int(level)); }
    // Largest scale available (raw_scale when there are no levels).
    float max_scale() const { return empty() ? raw_scale : level_scale(levels.size() - 1); }
};

// The mean length of the faces' edges (each interior edge counted from both
// of its faces), skipping zero and non-finite ones: the unit of the scales.
float mean_edge_length(const Mesh& mesh);

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

// The surface at scale sigma[v]: the normals of normals_at_scale and the
// positions, each vertex moved along the fitted normals onto the fitted
// surfaces of its levels (each cluster's quadric, level_fit.h's height),
// blended as the normals are (the raw estimate's share does not move), by at
// most sigma[v]. A smoothing without shrinkage: a sphere keeps its radius.
// Where sigma[v] <= raw_scale, and at flagged vertices, the mesh's own.
struct SurfaceAtScale {
    std::vector<glm::vec3> positions, normals;
};
SurfaceAtScale surface_at_scale(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw,
                                const std::vector<float>& sigma);

// The same with one sigma for every vertex.
SurfaceFields fields_at_scale(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw, float sigma);

// --- The same work in steps, for callers that spread it over time (a page
// with one thread: render/fields/detail_fields_job.h). The results are
// those of the functions above, bit for bit.

// The levels that fields at scales sigma blend from and that are not fitted yet.
std::vector<size_t> levels_to_fit(const ScaleSpace& space, const std::vector<float>& sigma);
// Fits these levels in one go, side by side on the threads.
void fit_levels(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw, const std::vector<size_t>& levels);

// Fits one level: its clusters in one step, the fit (level_fit.h's
// LevelFitter) over `chunk` clusters a step (0: each phase in one step), then
// the heights. The level counts as fitted only after the last step, so a
// fit left unfinished leaves the space as good as it was.
class LevelFitSteps {
public:
    LevelFitSteps(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw, size_t level, size_t chunk);
    bool done() const;
    void step();

private:
    const Mesh& mesh_;
    ScaleSpace& space_;
    const SurfaceFields& raw_;
    size_t level_, chunk_;
    std::unique_ptr<LevelFitter> fitter_;
};

// fields_at_scale's output before the blend (raw's fields, curvature zero where raw has none);
// blend_fields then blends vertices [first, last). The levels the blend reads must be fitted.
SurfaceFields fields_to_blend(const Mesh& mesh, const SurfaceFields& raw);
void blend_fields(const Mesh& mesh, const ScaleSpace& space, const SurfaceFields& raw,
                  const std::vector<float>& sigma, size_t first, size_t last, SurfaceFields& out);
// surface_at_scale's blend of vertices [first, last) into out, which starts as {mesh.positions, raw.normals}.
void blend_surface(const Mesh& mesh, const ScaleSpace& space, const SurfaceFields& raw,
                   const std::vector<float>& sigma, size_t first, size_t last, SurfaceAtScale& out);

}  // namespace kappa
