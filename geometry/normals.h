// Per-vertex normals with Max's weights (N. Max, "Weights for computing
// vertex normals from facet normals", JGT 1999): each face normal weighted
// by the face area over the squared lengths of the two edges at the vertex.
// Exact for vertices whose one-ring lies on a sphere.
#pragma once

#include "face_geometry.h"
#include "vertex_faces.h"

#include <glm/vec3.hpp>
#include <vector>

namespace kappa {

// Unit normals; a vertex with no non-degenerate face gets the zero vector
// (the caller flags it and substitutes a fallback).
std::vector<glm::vec3> compute_vertex_normals(const VertexFaces& vf, const FaceGeometry& faces);

}  // namespace kappa
