// What preparing a mesh for drawing asks of every face, in passes that read
// each face's corners' positions once (on big meshes they lie all over memory,
// and one pass over them costs about as much as reading the file): the
// volumes that tell an inside-out mesh (orientation.h) and, for a crease angle
// above 0, the vertices where an edge may turn by more than it
// (crease_candidates.h).
#pragma once

#include "mesh.h"
#include "orientation.h"
#include "vertex_faces.h"

#include <cstdint>
#include <vector>

namespace kappa {

struct FaceSurvey {
    EnclosedVolumes volumes;
    std::vector<uint32_t> crease_candidates;  // increasing; empty when the angle is 0
};

// vf: the mesh's rows (build_vertex_faces); read only for a crease angle above 0. The volumes are those of
// the tetrahedra from `apex` (any point: the signed sum of a closed mesh does not depend on it) to each
// face; a point inside the mesh's box keeps their terms small. Without one, the vertices' centroid (one
// more pass over the positions).
FaceSurvey survey_faces(const Mesh& mesh, const VertexFaces& vf, float crease_angle_deg, glm::vec3 apex);
FaceSurvey survey_faces(const Mesh& mesh, const VertexFaces& vf, float crease_angle_deg);
// The crease candidates alone (the same passes).
std::vector<uint32_t> crease_candidates(const Mesh& mesh, const VertexFaces& vf, float angle_deg);

}  // namespace kappa
