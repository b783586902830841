// Per-face quantities that normals, areas and curvature all need, computed
// in one pass over the faces (in double precision, stored as float), into
// the faces' records (face_record.h, phase 1).
#pragma once

#include "face_record.h"
#include "geometry/mesh/mesh.h"

#include <glm/vec3.hpp>

namespace kappa {

struct FaceGeometry {
    FaceRecords records;  // one a face, phase 1

    size_t size() const { return records.size(); }
    // (p1 - p0) x (p2 - p0): the face normal times twice the area. Zero for a
    // degenerate face (degenerate.h); such faces get zero weight everywhere.
    glm::vec3 area_normal(size_t f) const { return records[f].area_normal(); }
    // Mixed Voronoi area of each corner (voronoi_areas.h); they sum to the face area.
    glm::vec3 corner_areas(size_t f) const { return records[f].weights; }
};

FaceGeometry compute_face_geometry(const Mesh& mesh);

}  // namespace kappa
