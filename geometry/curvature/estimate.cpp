#include "estimate.h"

#include "estimator.h"
#include "jet.h"
#include "normal_fit.h"
#include "points_normals_fit.h"
#include "tensor_averaging.h"

#include "tensor_frames.h"

namespace kappa {

CurvatureEstimate empty_estimate(size_t nv, bool with_dcurv) {
    CurvatureEstimate out;
    out.tensors.tensor.assign(nv, Tensor2{});
    if (with_dcurv) out.dcurv_uv.assign(nv, glm::vec4(0.0f));
    out.flags.assign(nv, 0);
    return out;
}

VertexFrame vertex_frame(const EstimatorInput& in, size_t v) {
    glm::vec3 u, w;
    tangent_frame(in.normals[v], u, w);
    return {glm::dvec3(in.mesh.positions[v]), glm::dvec3(u), glm::dvec3(w), glm::dvec3(in.normals[v])};
}

CurvatureEstimate estimate_curvature(Estimator estimator, const EstimatorInput& in) {
    switch (estimator) {
    case Estimator::jet: return estimate_jet(in);
    case Estimator::tensor_averaging: return estimate_tensor_averaging(in);
    case Estimator::normal_fit: return estimate_normal_fit(in);
    case Estimator::points_normals_fit: return estimate_points_normals_fit(in);
    case Estimator::rusinkiewicz: break;
    }
    return {};
}

}  // namespace kappa
