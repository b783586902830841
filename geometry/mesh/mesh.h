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

}  // namespace kappa
