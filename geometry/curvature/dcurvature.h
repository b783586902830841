// Derivative of curvature (Rusinkiewicz 2004, sec. 3.4): the same scheme as
// curvature.h one order up. Per face, the vertices' curvature tensors are
// rotated into the face frame, and C = (a, b, c, d) is fitted by least
// squares to their differences along the edges:
//   d(ku) = a u + b v,  d(kuv) = b u + c v,  d(kv) = c u + d v.
// The face tensors are then rotated into each vertex's principal frame
// (d1, d2) and averaged with corner-area weights.
#pragma once

#include "curvature.h"

#include <glm/vec4.hpp>
#include <vector>

namespace kappa {

// `fits` and `tensors` from compute_curvature_tensors (tensors possibly
// smoothed), d1 from principal_curvatures of those tensors; the weights are
// the fits' corner areas. Returns (a, b, c, d) = (C111, C112, C122, C222) in each
// vertex's (d1, d2). Takes `fits` and `tensors` over (std::move them in):
// what the last pass does not need is freed before it allocates its output.
std::vector<glm::vec4> compute_dcurv(const Mesh& mesh, const VertexFaces& vf, FaceRecords fits,
                                     const std::vector<glm::vec3>& normals, VertexTensors tensors,
                                     const std::vector<glm::vec3>& d1);

}  // namespace kappa
