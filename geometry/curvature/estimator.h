// Which curvature estimator compute_surface_fields uses
// (docs/estimators-and-accuracy.md). Every estimator fills the same SurfaceFields.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace kappa {

enum class Estimator {
    rusinkiewicz,        // Rusinkiewicz 2004: per-face fits of normal differences (the default)
    jet,                 // degree-4 osculating jet over the 2-ring (Cazals & Pouget 2003): jet.h
    tensor_averaging,    // Cohen-Steiner & Morvan 2003 on the 1-ring: tensor_averaging.h
    normal_fit,          // fit of edge normal curvatures on the 1-ring: normal_fit.h
    points_normals_fit,  // Goldfeather & Interrante 2004 cubic fit on the 1-ring: points_normals_fit.h
};

// The command-line names, in enum order: rusinkiewicz, jet, tensor-averaging,
// normal-fit, points-normals-fit.
const std::vector<std::string>& estimator_names();
const std::string& estimator_name(Estimator e);
std::optional<Estimator> parse_estimator(const std::string& name);

}  // namespace kappa
