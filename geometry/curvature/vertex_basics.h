// What every vertex needs before curvature, in one pass over each vertex's
// faces (one record a face, face_record.h: one cache line each):
//  - its point area: the sum of its mixed-Voronoi corner areas (Meyer,
//    Desbrun, Schroeder & Barr 2002, sec. 3.3);
//  - its normal, with Max's weights (N. Max, "Weights for computing vertex
//    normals from facet normals", JGT 1999): each face normal weighted by
//    the face area over the squared lengths of the two edges at the vertex;
//    exact for vertices whose one-ring lies on a sphere;
//  - its reliability flags (vertex_flags.h), from its one-ring alone (so
//    the pass is parallel and needs no global edge table): isolated (no
//    face), degenerate (zero point area), boundary (an edge at the vertex
//    used by one face), non-manifold (an edge used by three or more faces).
#pragma once

#include "face_geometry.h"
#include "geometry/mesh/vertex_faces.h"

#include <glm/vec3.hpp>
#include <cstdint>
#include <vector>

namespace kappa {

struct VertexBasics {
    std::vector<float> point_areas;
    std::vector<uint8_t> flags;
    // Unit normals; a vertex with no non-degenerate face gets the zero
    // vector (it is flagged; the caller substitutes a fallback).
    std::vector<glm::vec3> normals;
};

VertexBasics compute_vertex_basics(const VertexFaces& vf, const FaceGeometry& faces);

}  // namespace kappa
