// How much the mesh bends at its edges, in one pass: what the crease angle's
// `auto` (creases.h, auto_crease_angle) and the creases themselves
// (find_creases) are decided from.
//
// The pass walks each vertex's faces (vertex_faces.h) instead of building an
// edge table: the edges (v, w) with w > v are found among the faces around v,
// so each edge is met once, at its smaller vertex. Face normals are computed
// once per face. On the 17.8M-face subdivided bunny this is several times
// cheaper than two edge tables and four normals per edge
// (bench/bench_preparation.cpp).
#pragma once

#include "mesh.h"
#include "vertex_faces.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace kappa {

struct EdgeBends {
    size_t interior = 0;  // edges shared by exactly two faces, both with a normal
    size_t between = 0;   // of those, the ones turning by more than 0.5 and at most kAutoCreaseAngle degrees
    std::vector<glm::uvec2> creases;       // interior edges turning by more than the angle asked: (v0 < v1), sorted
    std::vector<glm::uvec2> crease_faces;  // the two faces of each crease, lower first
};

// The unit normal of every face (creases.h, face_normal), in parallel.
std::vector<glm::vec3> face_normals(const Mesh& mesh);

// The bends of every edge (only valid faces count, as in edge_table.h);
// creases turning by more than `angle_deg` (none when angle_deg <= 0).
// Deterministic, whatever the thread count.
EdgeBends measure_edge_bends(const Mesh& mesh, const VertexFaces& vf, float angle_deg);
// The same for the edges met at the listed vertices only (sorted, distinct):
// the edges (v, w) with w > v around each. With per_vertex, each vertex's
// own counts too, as (interior, between). Cheaper than the whole pass when
// the list is short (the normals are computed as needed): a sample of the
// vertices (crease_vote.h), or the few where an edge may be a crease
// (crease_candidates.h).
EdgeBends measure_edge_bends_at(const Mesh& mesh, const VertexFaces& vf, float angle_deg,
                                const std::vector<uint32_t>& vertices, std::vector<glm::uvec2>* per_vertex = nullptr);

}  // namespace kappa
