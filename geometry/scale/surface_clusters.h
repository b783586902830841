// Surface patches ("clusters") of about one grid cell: the samples on
// which kappa's scale space fits its fields at one scale
// (geometry/scale/scale_space.h).
//
// The clusters are the connected pieces of the mesh inside the cells of a
// 3D grid (cell size `cell`, cells aligned at `origin`): two vertices share
// a cluster when a chain of mesh edges joins them without leaving their
// cell. Joining only along the mesh keeps the two sides of a thin sheet (an
// ear, a fin) apart even when one cell holds both. Each cluster carries its
// area (sum of the vertices' Voronoi areas), area-weighted centroid and
// area-weighted sum of vertex normals; two clusters are adjacent when a mesh
// edge joins them.
//
// Clusters are numbered along a Z-order curve through their cells (the
// pieces of one cell by their first vertex), so that neighbouring clusters
// have near numbers: the fits' visits of each cluster's neighbours
// (level_fit.h) stay in the cache (on a 17.8M-face mesh the finest level's
// fit went from 7.5-8.7 s to 2.9-3.1 s on 2 threads). Built on one thread in
// index order: cluster numbering and every sum are deterministic.
// O(V log V + F).
#pragma once

#include "geometry/mesh/mesh.h"

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
    bool built() const { return !vertex_cluster.empty(); }
};

// point_areas and normals: one per vertex (SurfaceFields). An empty mesh or
// a cell that is not positive and finite gives an empty level.
ClusterLevel build_surface_clusters(const Mesh& mesh, const std::vector<float>& point_areas,
                                    const std::vector<glm::vec3>& normals, glm::vec3 origin, float cell);

}  // namespace kappa
