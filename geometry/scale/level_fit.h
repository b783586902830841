// The fields of one level of the scale space (scale_space.h), fitted on its
// clusters (surface_clusters.h) as Rusinkiewicz 2004 fits them on faces, but
// over a smooth neighbourhood of about one cell:
//   1. normal: the clusters' area-weighted mean normals averaged with
//      weights scale_kernel(A_Q, d^2, 1 / R^2) over the clusters Q within
//      R = 2 cells, reached through cluster adjacency and facing the same
//      way (mean normals with a positive dot product);
//   2. curvature: the weighted least-squares fit of II in each cluster's
//      tangent frame from normal differences along centroid differences,
//      II e = dn (the paper's eq. 3, neighbours in place of a face's edges);
//   3. C: the same fit of the derivative tensor from curvature differences,
//      C(e) = dII (sec. 3.4), the neighbours' tensors restricted to the
//      cluster's frame.
// A cluster whose neighbours cannot support a fit (fewer than two, or all
// on a line) is marked not valid and never read. Every cluster's result is
// written by one thread: deterministic for any thread count.
#pragma once

#include "surface_clusters.h"
#include "tensor3.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace kappa {

struct ScaleLevelFields {
    // One record per cluster, packed for the per-vertex blend.
    struct Value {
        glm::vec3 normal;     // unit
        Sym3 curvature;       // II as a tensor of 3D space (tensor3.h)
        SymCubic3 dcurv;      // C as a tensor of 3D space
    };
    std::vector<Value> value;
    std::vector<uint8_t> valid;     // 0 where the cluster had too little around it for a fit
    std::vector<glm::vec4> place;   // centroid, and area or 0 where not valid
    // Where the fitted surface passes above the centroid, along the normal:
    // the cluster's surface is n . (x - centroid) = height - II(t, t) / 2
    // (t: the tangential part of x - centroid). Empty until fit_level_heights.
    std::vector<float> height;

    bool fitted() const { return !valid.empty(); }
};

ScaleLevelFields fit_level(const ClusterLevel& level);

// fit_level in steps, for callers that spread the work over time (a page
// with one thread, render/fields/detail_fields_job.h): the neighbourhoods,
// then the normals, II and C, each phase over `chunk` clusters a step
// (0: all of them in one step, on all threads). The same fields, bit for bit.
// `level` must outlive the fitter.
class LevelFitter {
public:
    explicit LevelFitter(const ClusterLevel& level, size_t chunk = 0);
    bool done() const { return phase_ == Phase::Done; }
    void step();
    ScaleLevelFields take();  // once done

    // Every cluster's fit neighbourhood, with kernel weights, in compressed rows.
    struct NeighbourLists {
        std::vector<uint32_t> offsets, cluster;
        std::vector<float> weight;
    };

private:
    enum class Phase { Neighbourhoods, Normals, Curvature, Dcurv, Done };
    void fit_normals(size_t first, size_t last);
    void fit_curvature(size_t first, size_t last);
    void fit_dcurv(size_t first, size_t last);
    void finish();

    const ClusterLevel& level_;
    size_t chunk_, next_ = 0;
    Phase phase_ = Phase::Neighbourhoods;
    std::vector<glm::vec3> dir_;  // unit mean normal of each cluster (0: none)
    NeighbourLists nb_;
    std::vector<Tensor2> curvature_;  // II in each cluster's tangent frame
    ScaleLevelFields out_;
};

// Fills fields.height: the offset that makes each cluster's quadric
// (normal and II of the fit) pass through its vertices in the area-weighted
// least-squares sense. The centroid of a curved patch lies inside it (by
// about II r^2 / 4 over a patch of radius r): without the offset, surfaces
// drawn from the fits would shrink. positions and point_areas: the mesh's,
// one per vertex. One thread; O(V).
void fit_level_heights(const ClusterLevel& level, const std::vector<glm::vec3>& positions,
                       const std::vector<float>& point_areas, ScaleLevelFields& fields);

// The smooth kernel of the fits and of the per-vertex blend: area x
// (1 - d^2 / R^2)^2 within R, a bump close to a Gaussian of sigma = R / 2.5,
// cheaper than exp().
inline float scale_kernel(float area, float d2, float inv_r2) {
    const float x = 1.0f - d2 * inv_r2;
    return x > 0 ? area * x * x : 0.0f;
}

}  // namespace kappa
