// The one interface every estimator other than the default implements
// (geometry/curvature/*.h): from the mesh and the paper's vertex normals,
// a curvature tensor per vertex and, where the method gives it natively,
// the derivative of curvature C. compute_surface_fields turns the result
// into SurfaceFields (principal curvatures and directions, C in the
// principal frame, smoothing), so every estimator fills the same fields.
//
// Boundary policy, shared by all: an estimator uses whatever one-sided
// neighbourhood a boundary vertex has (such vertices are flagged
// kFlagBoundary by the pipeline already); a vertex whose neighbourhood
// cannot support the estimator's model gets a finite fallback and the
// kFlagFallback bit. No estimator ever writes NaN or infinity.
#pragma once

#include "curvature.h"
#include "face_geometry.h"
#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace kappa {

struct EstimatorInput {
    const Mesh& mesh;
    const VertexFaces& vf;
    const FaceGeometry& faces;             // area normals and corner areas
    const std::vector<glm::vec3>& normals;  // unit Max (1999) normals, (0,0,1) where undefined
    const std::vector<float>& point_areas;  // mixed Voronoi areas
};

struct CurvatureEstimate {
    // The estimator's own unit normals; empty when it keeps the input normals.
    std::vector<glm::vec3> normals;
    // II per vertex in tangent_frame(normal) (tensor_frames.h), normal the
    // estimator's own where it gives one, else the input's.
    VertexTensors tensors;
    // C = (C111, C112, C122, C222) in the same frame (u, v); empty when the
    // estimator does not give C: the pipeline then runs the C step of
    // Rusinkiewicz 2004 (sec. 3.4, dcurvature.h) on `tensors`.
    std::vector<glm::vec4> dcurv_uv;
    // Per-vertex bits to add to the flags (kFlagFallback); empty: none.
    std::vector<uint8_t> flags;
};

}  // namespace kappa

namespace kappa {

// An estimate for nv vertices with zero tensors, no flags, and zero C when
// `with_dcurv` (estimators fill it in).
CurvatureEstimate empty_estimate(size_t nv, bool with_dcurv);

// Vertex v's position and the frame (u, w, n) of its input normal, n =
// u x w, u and w from tangent_frame: the frame the fits work in.
struct VertexFrame {
    glm::dvec3 p, u, w, n;
};
VertexFrame vertex_frame(const EstimatorInput& in, size_t v);

enum class Estimator;

// Runs one of the estimators above (not Estimator::rusinkiewicz, which the
// pipeline runs itself: curvature.h, dcurvature.h).
CurvatureEstimate estimate_curvature(Estimator estimator, const EstimatorInput& in);

}  // namespace kappa
