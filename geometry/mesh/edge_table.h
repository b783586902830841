// The undirected edges of a triangle mesh, each listed once, with the faces
// that use it. Half-edge h = 3 f + i of face f runs from f[i] to f[(i+1) % 3].
//
// Only "valid" faces contribute: three distinct vertex indices, all in range.
// Faces that repeat an index have no meaningful edges; they are reported as
// degenerate by mesh_stats.h and otherwise ignored by the topology.
#pragma once

#include "mesh.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace kappa {

struct EdgeTable {
    std::vector<glm::uvec2> ends;     // (v0, v1) with v0 < v1, sorted lexicographically
    std::vector<uint32_t> first;      // size E + 1: the half-edges of edge e are
    std::vector<uint32_t> halfedges;  //   halfedges[first[e] .. first[e+1]), by increasing face

    size_t size() const { return ends.size(); }
    // Number of faces using edge e: 1 on a boundary, 2 inside a manifold, > 2 non-manifold.
    uint32_t face_count(size_t e) const { return first[e + 1] - first[e]; }
};

inline bool is_valid_face(const Face& f, size_t vertex_count) {
    return f[0] != f[1] && f[1] != f[2] && f[2] != f[0] && f[0] < vertex_count && f[1] < vertex_count &&
           f[2] < vertex_count;
}

// Sorts keys in place: insertion sort for the short runs a vertex's edges give (most hold 2 to
// 12 keys), std::sort beyond 32. Used wherever edges are gathered around one vertex.
void sort_short_run(uint64_t* begin, uint64_t* end);

// Counting sort of the half-edges by their smaller vertex, then a sort of each
// vertex's short bucket by the larger vertex: O(V + F) plus tiny sorts.
// Deterministic (independent of the thread count). Tens of milliseconds for
// the 1.1M-face bunny (bench/bench_topology.cpp); big buffers are prefaulted
// because first-touch page faults otherwise dominate on VMs.
EdgeTable build_edge_table(const Mesh& mesh);

}  // namespace kappa
