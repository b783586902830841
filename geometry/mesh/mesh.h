// The triangle mesh every part of kappa works on: positions and triangles,
// nothing else. Vertex order is the input order (curvature is reported per
// input vertex), faces are counter-clockwise seen from outside.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace kappa {

using Face = glm::uvec3;  // three vertex indices

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<Face> faces;

    size_t vertex_count() const { return positions.size(); }
    size_t face_count() const { return faces.size(); }
};

// The room a reader reserves for n positions: n and a little more, for the
// vertex copies a split along creases appends (creases.h), which would
// otherwise move the whole array (tens of ms on a mesh of millions).
inline size_t positions_room(size_t n) { return n + n / 256 + 64; }

}  // namespace kappa
