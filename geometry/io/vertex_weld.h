// Exact vertex welding for triangle soups (STL stores each triangle with its
// own three corners).
#pragma once

#include "geometry/mesh/mesh.h"

#include <vector>

namespace kappa::io {

// Builds a mesh from triangle corners (3 per triangle), merging corners whose
// coordinates are exactly equal (-0 equals +0). Vertices are numbered in
// order of first occurrence, so the result is deterministic.
Mesh weld_exact(const std::vector<glm::vec3>& corners);

}  // namespace kappa::io
