// Combinatorial facts about a triangle mesh: boundaries, non-manifold edges,
// boundary loops, connected components, isolated vertices, Euler
// characteristic. No geometry (see mesh_stats.h for lengths and bounds).
//
// Definitions (faces that repeat an index or use one out of range are
// "invalid" and ignored here, see edge_table.h):
//   boundary edge      used by exactly one valid face
//   non-manifold edge  used by three or more valid faces
//   boundary loop      a closed walk along boundary edges, the way a
//                      half-edge structure traces a hole. At each vertex the
//                      faces around it split into fans ("wedges") of faces
//                      joined through two-face edges; the two boundary edges
//                      that end a fan are consecutive on a loop. So two
//                      triangles that share only a vertex (a bowtie) have two
//                      loops, while two holes of a sphere that touch at one
//                      vertex are walked as one figure-eight loop (the
//                      count after splitting every vertex into its fans). A
//                      fan that ends on a non-manifold edge leaves its
//                      boundary edge unpaired there; such an open chain still
//                      counts as one loop.
//   component          vertices joined by faces (every face joins its three
//                      vertices; faces touching at a single vertex are one
//                      component). Isolated vertices are not components.
//   isolated vertex    used by no face
//   Euler char. chi    V - E + F over the valid faces: V the vertices they
//                      use, E their distinct edges, F their number.
//                      Closed orientable surface of genus g, b holes:
//                      chi = 2 - 2 g - b per component.
#pragma once

#include "edge_table.h"
#include "mesh.h"

#include <cstdint>
#include <vector>

namespace kappa {

struct Topology {
    size_t surface_vertices = 0;  // vertices used by valid faces
    size_t valid_faces = 0;
    size_t edges = 0;
    size_t boundary_edges = 0;
    size_t nonmanifold_edges = 0;
    size_t boundary_loops = 0;
    size_t components = 0;
    size_t isolated_vertices = 0;
    long long euler_characteristic = 0;
};

Topology analyze_topology(const Mesh& mesh, const EdgeTable& edges);

size_t count_boundary_loops(const Mesh& mesh, const EdgeTable& edges);

constexpr uint32_t kNoComponent = UINT32_MAX;

struct Components {
    size_t count = 0;
    size_t isolated_vertices = 0;
    // Per vertex: component 0..count-1, numbered in order of their smallest
    // vertex index; kNoComponent for isolated vertices.
    std::vector<uint32_t> label;
};

Components find_components(const Mesh& mesh);

// Per-vertex boundary / non-manifold flags: compute_vertex_basics (vertex_basics.h).

}  // namespace kappa
