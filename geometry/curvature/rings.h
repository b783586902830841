// Vertex neighbourhoods for the fitting estimators: the vertex-to-vertex
// adjacency (CSR) and k-rings gathered by breadth-first search.
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"

#include <cstdint>
#include <vector>

namespace kappa {

struct VertexAdjacency {
    std::vector<uint32_t> offsets;     // size V + 1
    std::vector<uint32_t> neighbours;  // each row sorted, no repeats, the vertex itself excluded

    uint32_t begin(size_t v) const { return offsets[v]; }
    uint32_t end(size_t v) const { return offsets[v + 1]; }
};

// The other two corners of every face at each vertex, sorted and deduplicated.
VertexAdjacency build_vertex_adjacency(const Mesh& mesh, const VertexFaces& vf);

// Collects k-rings of one vertex at a time. Keeps a mark per mesh vertex, so
// make one per thread (per parallel range), not per vertex. The order of the
// ring (breadth-first, each row in adjacency order) depends on the mesh
// only, so fits over it are deterministic.
class RingCollector {
public:
    explicit RingCollector(size_t vertex_count) : mark_(vertex_count, 0) {}

    // The vertex and every vertex at most `rings` edges away, the vertex first.
    const std::vector<uint32_t>& collect(const VertexAdjacency& adj, uint32_t v, int rings);
    // Adds one more ring to the last collect(); returns the new ring count.
    int grow(const VertexAdjacency& adj);
    const std::vector<uint32_t>& ring() const { return ring_; }

private:
    std::vector<uint32_t> mark_;  // == epoch_: in ring_
    uint32_t epoch_ = 0;
    std::vector<uint32_t> ring_;
    size_t frontier_begin_ = 0;  // the last ring added: ring_[frontier_begin_, end)
    int rings_ = 0;
};

}  // namespace kappa
