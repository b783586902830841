// What preparing a mesh for drawing asks of every face, in one parallel pass
// over the faces (on big meshes their corners' positions are read from all
// over memory, and each pass costs about as much as reading the file): the
// volumes that tell an inside-out mesh (orientation.h) and, for a crease angle
// above 0, the vertices where an edge may turn by more than it
// (crease_candidates.h).
#pragma once

#include "mesh.h"
#include "orientation.h"

#include <cstdint>
#include <vector>

namespace kappa {

struct FaceSurvey {
    EnclosedVolumes volumes;
    std::vector<uint32_t> crease_candidates;  // increasing; empty when the angle is 0
};

FaceSurvey survey_faces(const Mesh& mesh, float crease_angle_deg);
// The crease candidates alone (the same pass).
std::vector<uint32_t> crease_candidates(const Mesh& mesh, float angle_deg);

}  // namespace kappa
