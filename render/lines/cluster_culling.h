// Cluster culling for the contour pass: the triangles are uploaded cluster
// by cluster (geometry/culling/face_clusters.h), and per frame the CPU picks the
// runs of clusters that can hold a line in this view, so the geometry
// shader (shaders/lines/isolines_geom.glsl) never runs on the others. A cluster
// is skipped when
//   - its bounding sphere lies outside the view (widened by the line width),
//   - it is entirely back-facing (geometry/culling/cluster_bounds.h): n.v < 0 at
//     every vertex, so no contour (a sign change of n.v) and no suggestive
//     contour (drawn only where n.v > 0),
//   - it is entirely front-facing and cannot hold a suggestive contour:
//     kr sin^2(theta) = k1 u^2 + k2 t^2 keeps one sign where k1 and k2 do
//     (elliptic vertices), or every triangle has an unreliable vertex (the
//     shader skips those), or the test Dw kr fs^2 > s fails at every
//     vertex whatever the view. Where n.v > 0, Dw kr = C(w,w,w) - 2 tau^2
//     cot(theta) <= C(w,w,w) <= sqrt(a^2 + 3b^2 + 3c^2 + d^2) for unit w
//     (Cauchy-Schwarz with (w1^3, sqrt3 w1^2 w2, sqrt3 w1 w2^2, w2^3),
//     whose length is (w1^2 + w2^2)^(3/2) = 1), and the shader only
//     interpolates vertex values.
// The result is exact: the same pixels as drawing every triangle.
#pragma once

#include "geometry/culling/cluster_bounds.h"
#include "geometry/culling/face_clusters.h"
#include "geometry/lines/line_extraction.h"
#include "geometry/mesh/mesh.h"
#include "geometry/surface_fields.h"
#include "render/camera/frame_params.h"
#include "render/render_settings.h"

#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace kappa::render {

struct MeshClusters {
    std::vector<ClusterBounds> bounds;          // sphere, and cone of the fields' normals
    std::vector<ClusterBounds> fine_bounds;  // cone of the fine normals, for contours (empty: the same as bounds)
    std::vector<uint32_t> first_face;  // size clusters + 1, in the uploaded (cluster) order
    std::vector<uint8_t> may_have_suggestive;
    std::vector<float> max_strength;  // bound on Dw kr fs^2 over the reliable front-facing vertices, any view
    // View-independent bounds for the curvature lines, over the faces whose
    // vertices are all reliable (the shaders skip the others):
    std::vector<uint8_t> may_have_parabolic;  // a face whose vertices' K = k1 k2 differ in sign (> 0 or not)
    std::vector<uint8_t> may_have_mean_zero;  // likewise H = (k1 + k2) / 2
    std::vector<float> max_kmax;              // largest |kmax| fs: ridges and valleys need more than the threshold
    std::vector<float> max_highlight;         // largest (kmax^2 - kmin^2) fs^2: principal highlights likewise

    size_t size() const { return bounds.size(); }
};

// fields must have one entry per vertex (flags may be empty); feature_size:
// fs, as given to the shaders; fine_normals: empty, or one per vertex
// when occluding contours use normals of their own (MeshBuffers).
MeshClusters make_mesh_clusters(const Mesh& mesh, const SurfaceFields& fields, const FaceClusters& clusters,
                                float feature_size, const std::vector<glm::vec3>& fine_normals = {});

// The same in pieces, for callers that spread the work over time
// (render/fields/field_upload.h): the clusters' spheres and normal cones,
// then the curvature bounds of clusters [first, last) from what they need
// of each vertex.
struct VertexBounds {
    float kmax = 0;       // max(|k1|, |k2|) fs
    float highlight = 0;  // (kmax^2 - kmin^2) fs^2
    double strength = 0;  // |C| fs^2 (dcurv_norm), as the shader bounds Dw kr
    bool reliable = false, k2_positive = false, k1_negative = false, positive_k = false, positive_h = false;
};
MeshClusters mesh_cluster_bounds(const Mesh& mesh, const SurfaceFields& fields, const FaceClusters& clusters,
                                 const std::vector<glm::vec3>& fine_normals);
std::vector<VertexBounds> vertex_bounds(const SurfaceFields& fields, float fs);
void bound_cluster_curvature(const Mesh& mesh, const FaceClusters& clusters, const std::vector<VertexBounds>& vb,
                             size_t first, size_t last, MeshClusters& out);

struct FaceRun {
    uint32_t first, count;  // faces [first, first + count) of the uploaded order
};

// The surface pass, culling back faces (render/surface/back_face_culling.h), draws
// only the clusters in view that are not entirely back-facing: the others'
// faces would all be clipped or culled, after their vertices were shaded.
std::vector<FaceRun> front_surface_runs(const MeshClusters& clusters, const FrameParams& frame);
// Its back faces then come from the clusters that are not entirely
// front-facing and reach into one of these pixel rectangles (x, y, width,
// height) of the view: those whose back faces a hole there may show.
std::vector<FaceRun> back_facing_runs_in(const MeshClusters& clusters, const FrameParams& frame,
                                         const std::vector<glm::ivec4>& rects);

// The runs of faces the contour pass must draw for this frame. margin_px:
// how far outside the image a line may still cover pixels inside it;
// sc_threshold: the dimensionless s of the suggestive-contour test;
// any_front: also every cluster not entirely back-facing (the Dw kr lines,
// drawn wherever n.v > 0).
std::vector<FaceRun> contour_pass_runs(const MeshClusters& clusters, const FrameParams& frame, bool contours,
                                       bool suggestive, float sc_threshold, float margin_px, bool any_front = false);

// The other line passes skip the clusters outside the view, the entirely
// back-facing ones unless `back_facing` (hidden lines drawn: their lines
// are behind the front surface, only within the occlusion tolerance next to
// a contour, half an edge, could one have shown), and those that cannot hold
// a line of the kinds on:
//   curvature_line_runs: ridges and valleys (rv_threshold: their S), K = 0, H = 0
//     (shaders/lines/curvature_lines_geom.glsl), from MeshClusters' bounds;
//   view_ridge_runs: apparent ridges (none skipped: the view-dependent
//     curvature has no bound) and principal highlights (ph_threshold: their s);
//   isophote_runs, topo_runs: below.
std::vector<FaceRun> curvature_line_runs(const MeshClusters& clusters, const FrameParams& frame, bool back_facing,
                                         float margin_px, const LineSelection& lines, float rv_threshold);
std::vector<FaceRun> view_ridge_runs(const MeshClusters& clusters, const FrameParams& frame, bool back_facing,
                                     float margin_px, const LineSelection& lines, float ph_threshold);

// The clusters that can cross a level: isophotes (n.l
// with the unit light direction over the cone of the fields' normals) and
// topographic lines (heights y over the bounding sphere). Exact: the values
// interpolated over a triangle lie between its vertices'.
std::vector<FaceRun> isophote_runs(const MeshClusters& clusters, const FrameParams& frame, bool back_facing,
                                   float margin_px, glm::vec3 light, const LevelSet& levels);
std::vector<FaceRun> topo_runs(const MeshClusters& clusters, const FrameParams& frame, bool back_facing,
                               float margin_px, const LevelSet& levels);

}  // namespace kappa::render
