#include "estimate.h"

#include "estimator.h"
#include "jet.h"
#include "normal_fit.h"
#include "points_normals_fit.h"
#include "tensor_averaging.h"

namespace kappa {

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
