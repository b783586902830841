// Errors of an estimator's raw output (geometry/curvature/estimate.h)
// against analytic truth, for tests and the accuracy lab that call an
// estimator directly with options of their own (JetOptions).
#pragma once

#include "analytic_curvature.h"

#include "geometry/curvature/estimate.h"
#include "geometry/curvature/face_geometry.h"
#include "geometry/curvature/vertex_basics.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/curvature/voronoi_areas.h"

namespace kappa::test {

// What an estimator takes, computed as compute_surface_fields does (Max
// normals, mixed Voronoi areas). Keep it alive while the input is used.
struct EstimatorInputs {
    VertexFaces vf;
    FaceGeometry faces;
    std::vector<glm::vec3> normals;
    std::vector<float> areas;

    EstimatorInput of(const Mesh& m) const { return {m, vf, faces, normals, areas}; }
};

inline EstimatorInputs estimator_inputs(const Mesh& m) {
    EstimatorInputs in{build_vertex_faces(m), compute_face_geometry(m), {}, {}};
    VertexBasics basics = compute_vertex_basics(in.vf, in.faces);
    in.normals = std::move(basics.normals);
    in.areas = std::move(basics.point_areas);
    return in;
}

struct RelativeErrors {
    double curvature = 0, dcurv = 0;  // as relative_curvature_error and relative_dcurv_error
};

// Relative errors of a CurvatureEstimate with its own normals (II and C in
// tangent_frame(normal)), measured like relative_*_error: the estimate's
// tensors as 3x3 forms, compared in the true normal's tangent frame. An
// estimate without C (dcurv_uv empty) gets a NaN C error.
inline RelativeErrors relative_errors(const CurvatureEstimate& e, const AnalyticMesh& a) {
    double ek = 0, rk = 0, ec = 0;
    const bool has_dcurv = !e.dcurv_uv.empty();
    for (size_t i = 0; i < a.normal.size(); ++i) {
        if (a.weight[i] == 0) continue;
        glm::vec3 fu, fv, tu, tv;
        tangent_frame(e.normals[i], fu, fv);
        tangent_frame(glm::vec3(a.normal[i]), tu, tv);
        const glm::dvec3 u(fu), v(fv), U(tu), V(tv);
        const Tensor2& t = e.tensors.tensor[i];
        const glm::dmat3 E =
            double(t.ku) * outer(u, u) + double(t.kuv) * (outer(u, v) + outer(v, u)) + double(t.kv) * outer(v, v);
        const glm::dmat3 D = E - a.shape[i];
        ek += mean_square_over_directions(glm::dot(U, D * U), glm::dot(U, D * V), glm::dot(V, D * V));
        rk += mean_square_over_directions(glm::dot(U, a.shape[i] * U), glm::dot(U, a.shape[i] * V),
                                          glm::dot(V, a.shape[i] * V));
        if (!has_dcurv) continue;
        const glm::dvec4 C = dcurv_in_tangent_frame(glm::dvec4(e.dcurv_uv[i]), u, v, a.normal[i]);
        ec += dcurv_norm2(C - a.dcurv[i]);
    }
    return {std::sqrt(ek / rk), has_dcurv ? std::sqrt(ec / dcurv_reference2(a)) : std::nan("")};
}

}  // namespace kappa::test
