// Apparent ridges and principal highlights on the CPU: the tests of
// shaders/lines/view_ridges_geom.glsl and the view-dependent curvature of
// shaders/common/view_curvature.glsl, per triangle with no unreliable vertex.
//   apparent ridges (Judd, Durand and Adelson 2007, Sec. 3): maxima of the
//     view-dependent curvature q1 along its principal direction t1, where
//     D_t1 q1 t1 changes direction along the triangle's edges and points
//     towards the line from both sides; kept where sqrt(q1) fs > threshold.
//   principal highlights (DeCarlo and Rusinkiewicz 2007): v.dmax = 0 where
//     kmax (the curvature of larger magnitude) has one sign over the
//     triangle, kept where (kmax^2 - kmin^2) n.v fs^2 > threshold.
// Both fade from 0 at the threshold to 1 at twice it (at least + 0.05).
#pragma once

#include "geometry/lines/line_extraction.h"

#include <glm/vec2.hpp>

namespace kappa {

// The view-dependent curvature at a point (Judd et al. 2007): q1 the largest
// eigenvalue of Q^T Q, Q = S (I + (sec(theta) - 1) w w^T) in the principal
// frame; t1 its unit eigenvector in (d1, d2) coordinates; dq1 its
// derivative along t1 per unit of projected length (from C, the paper's
// derivative of curvature; derivation in shaders/common/view_curvature.glsl).
struct ViewCurvature {
    float q1 = 0;
    glm::vec2 t1{1, 0};
    float dq1 = 0;
};
ViewCurvature view_curvature(float k1, float k2, glm::vec4 C, glm::vec3 n, glm::vec3 d1, glm::vec3 d2,
                             glm::vec3 to_eye);

struct ViewRidgeOptions {
    bool apparent_ridges = false, principal_highlights = false;
    float ar_threshold = 1.0f;  // dimensionless, on sqrt(q1) fs
    float ph_threshold = 0.2f;  // dimensionless, on (kmax^2 - kmin^2) n.v fs^2
    float feature_size = 1;
    bool fade = true;
};

// The segments of each, seen from `eye` (model coordinates).
void extract_view_ridges(const Mesh& mesh, const SurfaceFields& fields, glm::vec3 eye, const ViewRidgeOptions& options,
                         std::vector<LineSegment>& apparent_ridges, std::vector<LineSegment>& principal_highlights);

// The same in two steps, for passes that choose their triangles: per vertex
// once (parallel), then triangle by triangle.
struct ViewRidgeVertex {
    float view_curv;    // sqrt(q1) fs
    glm::vec3 t1;       // model coordinates
    float dq1;
    float kmax;         // the curvature of larger magnitude, signed
    glm::vec3 dmax;     // its direction
    float v_dmax;       // v.dmax
    float ph_strength;  // (kmax^2 - kmin^2) n.v fs^2
};
// only: empty, or one flag per vertex, non-zero where it is needed (the
// others are left zero).
std::vector<ViewRidgeVertex> view_ridge_vertices(const Mesh& mesh, const SurfaceFields& fields, glm::vec3 eye,
                                                 float feature_size, const std::vector<uint8_t>& only = {});
// The same into `out`, resized, not cleared: where `only` is zero it keeps
// what it held (for a caller that keeps it from frame to frame).
void view_ridge_vertices(const Mesh& mesh, const SurfaceFields& fields, glm::vec3 eye, float feature_size,
                         const std::vector<uint8_t>& only, std::vector<ViewRidgeVertex>& out);
// The same for the vertices [begin, end) alone, on the calling thread, into
// `out` already of one entry per vertex (for several per-vertex passes over
// one range while it is in cache).
void view_ridge_vertices(const Mesh& mesh, const SurfaceFields& fields, glm::vec3 eye, float feature_size,
                         const std::vector<uint8_t>& only, size_t begin, size_t end, std::vector<ViewRidgeVertex>& out);
void view_ridges_of_face(const Mesh& mesh, const Face& face, const SurfaceFields& fields,
                         const std::vector<ViewRidgeVertex>& vertices, const ViewRidgeOptions& options,
                         std::vector<LineSegment>& apparent_ridges, std::vector<LineSegment>& principal_highlights);

}  // namespace kappa
