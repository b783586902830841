// Per-face quantities that normals, areas and curvature all need, computed
// in one pass over the faces (in double precision, stored as float).
#pragma once

#include "mesh.h"

#include <glm/vec3.hpp>
#include <vector>

namespace kappa {

struct FaceGeometry {
    // (p1 - p0) x (p2 - p0): the face normal times twice the area. Zero for a
    // degenerate face (degenerate.h); such faces get zero weight everywhere.
    std::vector<glm::vec3> area_normals;
    // 1 / |e_j|^2 for the edge e_j opposite corner j (0 when degenerate).
    std::vector<glm::vec3> inv_edge_len2;
    // Mixed Voronoi area of each corner (voronoi_areas.h); they sum to the face area.
    std::vector<glm::vec3> corner_areas;

    bool degenerate(size_t f) const { return corner_areas[f] == glm::vec3(0.0f); }
};

FaceGeometry compute_face_geometry(const Mesh& mesh);

}  // namespace kappa
