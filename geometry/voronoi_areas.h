// Mixed Voronoi areas (Meyer, Desbrun, Schroeder & Barr 2002, sec. 3.3,
// Fig. 4): each triangle's area is split among its corners by the Voronoi
// regions of its vertices; in an obtuse triangle the obtuse corner gets half
// the area and the other two a quarter each. Degenerate faces get zero.
#pragma once

#include "mesh.h"
#include "vertex_faces.h"

#include <glm/vec3.hpp>
#include <vector>

namespace kappa {

// Per face, the area assigned to each of its three corners (they sum to the face area).
std::vector<glm::vec3> compute_corner_areas(const Mesh& mesh);

// Per vertex, the sum of its corner areas.
std::vector<float> compute_point_areas(const VertexFaces& vf, const std::vector<glm::vec3>& corner_areas);

}  // namespace kappa
