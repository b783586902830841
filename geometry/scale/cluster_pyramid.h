// A hierarchy of surface patches ("clusters") at doubling sizes, the
// skeleton of kappa's scale space (geometry/scale/scale_space.h).
//
// Level 0 clusters are the connected pieces of the mesh inside the cells of
// a 3D grid of cell size `first_cell`: two vertices share a cluster when a
// chain of mesh edges joins them without leaving their cell. Level k + 1
// uses cells twice as large (each the union of 2x2x2 cells of level k) and
// joins level-k clusters of one cell that are adjacent. Joining only along
// the mesh keeps the two sides of a thin sheet (an ear, a fin) apart even
// when one cell holds both. Each cluster carries its area (sum of the
// vertices' Voronoi areas), area-weighted centroid and area-weighted sum of
// vertex normals; two clusters are adjacent when a mesh edge joins them.
//
// Everything is built on one thread in index order: cluster numbering and
// every sum are deterministic. O(V + F) per level; the levels shrink by
// about 4 each.
#pragma once

#include "geometry/mesh.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace kappa {

struct ClusterLevel {
    float cell = 0;                        // grid cell size, model units
    std::vector<glm::vec3> centroid;       // area-weighted mean position
    std::vector<float> area;               // sum of the vertices' Voronoi areas
    std::vector<glm::vec3> normal_sum;     // sum of area x unit vertex normal
    std::vector<uint32_t> adj_offsets;     // CSR: neighbours of cluster c are
    std::vector<uint32_t> adj;             //   adj[adj_offsets[c] .. adj_offsets[c+1])
    std::vector<uint32_t> vertex_cluster;  // the cluster of each mesh vertex

    size_t size() const { return area.size(); }
};

struct ClusterPyramid {
    std::vector<ClusterLevel> levels;  // finest first
};

// Builds levels with cells first_cell, 2 first_cell, ... while the cell is
// at most max_cell and the level still has more than 8 clusters.
// point_areas and normals: one per vertex (SurfaceFields).
ClusterPyramid build_cluster_pyramid(const Mesh& mesh, const std::vector<float>& point_areas,
                                     const std::vector<glm::vec3>& normals, float first_cell, float max_cell);

}  // namespace kappa
