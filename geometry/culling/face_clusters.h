// Faces grouped into small, spatially coherent, connected clusters, for
// per-cluster culling on the CPU (cluster_bounds.h): the renderer draws or
// skips whole runs of faces by their cluster.
//
// Growth rule: breadth-first over faces that share a VERTEX (not only an
// edge). The vertex -> faces rows (vertex_faces.h) are a counting sort, so no
// edge table is needed; vertex rings give the same round, disk-like patches
// as edge adjacency on a manifold, and faces that touch only at a vertex
// (bow ties, non-manifold fans, faces with a repeated index) still join their
// neighbours instead of becoming tiny clusters of their own.
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"

#include <cstdint>
#include <vector>

namespace kappa {

struct FaceClusters {
    std::vector<uint32_t> face_order;  // permutation of 0..F-1: the faces cluster by cluster
    // Permutation of 0..V-1, new -> old: the vertices in order of first use
    // by the faces in face_order, then those no face uses. A renderer that
    // stores its vertices in this order finds a run of faces' vertices close
    // together in memory (the clusters reorder the faces, not the vertices).
    std::vector<uint32_t> vertex_order;
    std::vector<uint32_t> vertex_slot;  // old -> new: the inverse of vertex_order
    // Size clusters + 1; cluster c is face_order[cluster_start[c] .. cluster_start[c+1]).
    std::vector<uint32_t> cluster_start;
    size_t size() const { return cluster_start.empty() ? 0 : cluster_start.size() - 1; }
};

// Greedy region growing: a cluster starts at a seed face and takes the faces
// around its vertices ring by ring (breadth-first over vertices, each
// vertex's faces in increasing face order) until it has max_faces faces or
// its connected component is used up. The next seed is the first unassigned
// face met on the frontier of the previous cluster (so consecutive clusters
// are neighbours), or else the lowest-numbered unassigned face.
//
// Input:  mesh (vertex indices must be < vertex_count(); any other defect is
//         fine: isolated vertices, repeated indices, non-manifold edges),
//         max_faces >= 1 (0 is treated as 1), rows the mesh's vertex-face
//         rows (build_vertex_faces; null: built here).
// Output: every face in exactly one cluster, vertex_order and vertex_slot; each cluster has 1..max_faces
//         faces, all connected through shared vertices. An empty mesh gives
//         zero clusters (cluster_start = {0}). Deterministic, O(V + F).
FaceClusters cluster_faces(const Mesh& mesh, uint32_t max_faces = 256, const VertexFaces* rows = nullptr);

}  // namespace kappa
