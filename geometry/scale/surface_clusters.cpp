#include "surface_clusters.h"

#include "geometry/mesh/union_find.h"
#include "geometry/parallel/parallel.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

// Each interior edge is visited once (from the face where a < b); an open
// boundary edge only when its face lists it that way round, which at worst
// splits a cluster along the boundary.
template <typename Fn>
void for_each_edge(const Mesh& mesh, Fn&& fn) {
    for (const Face& f : mesh.faces)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = f[e], b = f[(e + 1) % 3];
            if (a < b) fn(a, b);
        }
}

// The cell's position along a Z-order (Morton) curve: 21 bits of each coordinate interleaved.
uint64_t z_order(glm::ivec3 cell) {
    auto spread = [](uint32_t x) {  // bit i to bit 3i
        uint64_t v = x & 0x1fffff;
        v = (v | v << 32) & 0x1f00000000ffffull;
        v = (v | v << 16) & 0x1f0000ff0000ffull;
        v = (v | v << 8) & 0x100f00f00f00f00full;
        v = (v | v << 4) & 0x10c30c30c30c30c3ull;
        v = (v | v << 2) & 0x1249249249249249ull;
        return v;
    };
    auto coordinate = [](int c) { return uint32_t(std::max(c, 0)); };  // cells start at the lowest corner
    return spread(coordinate(cell.x)) | spread(coordinate(cell.y)) << 1 | spread(coordinate(cell.z)) << 2;
}

}  // namespace

ClusterLevel build_surface_clusters(const Mesh& mesh, const std::vector<float>& point_areas,
                                    const std::vector<glm::vec3>& normals, glm::vec3 origin, float cell) {
    ClusterLevel level;
    const size_t n = mesh.vertex_count();
    if (n == 0 || !(cell > 0) || !std::isfinite(cell)) return level;
    level.cell = cell;
    std::vector<glm::ivec3> key(n);
    for (size_t v = 0; v < n; ++v) key[v] = glm::ivec3(glm::floor((mesh.positions[v] - origin) / cell));

    UnionFind uf(n);
    for_each_edge(mesh, [&](uint32_t a, uint32_t b) {
        if (key[a] == key[b]) uf.unite(a, b);
    });

    // Clusters numbered along a Z-order curve through their cells (pieces of one cell by
    // their first vertex): neighbours get near numbers, so the fits' visits of a cluster's
    // neighbours stay in the cache. Deterministic.
    level.vertex_cluster.resize(n);
    std::vector<uint32_t> root_cluster(n, UINT32_MAX);
    std::vector<uint64_t> order;  // (Z-order code of the cell, first-vertex number) per cluster
    uint32_t clusters = 0;
    for (size_t v = 0; v < n; ++v) {
        const uint32_t r = uf.find(uint32_t(v));
        if (root_cluster[r] == UINT32_MAX) {
            root_cluster[r] = clusters++;
            order.push_back(z_order(key[v]));
        }
        level.vertex_cluster[v] = root_cluster[r];
    }
    std::vector<glm::ivec3>().swap(key);
    std::vector<uint32_t>().swap(root_cluster);
    std::vector<uint32_t> rank(clusters);
    for (uint32_t k = 0; k < clusters; ++k) rank[k] = k;
    std::stable_sort(rank.begin(), rank.end(), [&](uint32_t a, uint32_t b) { return order[a] < order[b]; });
    std::vector<uint64_t>().swap(order);
    std::vector<uint32_t> renumbered(clusters);
    for (uint32_t k = 0; k < clusters; ++k) renumbered[rank[k]] = k;
    std::vector<uint32_t>().swap(rank);
    parallel_for(n, [&](size_t v) { level.vertex_cluster[v] = renumbered[level.vertex_cluster[v]]; });

    level.area.assign(clusters, 0.0f);
    level.normal_sum.assign(clusters, glm::vec3(0.0f));
    std::vector<glm::vec3> area_position(clusters, glm::vec3(0.0f));
    level.centroid.assign(clusters, glm::vec3(0.0f));  // plain position sums first
    std::vector<uint32_t> count(clusters, 0);
    for (size_t v = 0; v < n; ++v) {
        const uint32_t k = level.vertex_cluster[v];
        const float a = point_areas[v];
        level.area[k] += a;
        area_position[k] += a * mesh.positions[v];
        level.normal_sum[k] += a * normals[v];
        level.centroid[k] += mesh.positions[v];
        ++count[k];
    }
    for (uint32_t k = 0; k < clusters; ++k)
        level.centroid[k] = level.area[k] > 0 ? area_position[k] / level.area[k] : level.centroid[k] / float(count[k]);

    // Adjacency: count, fill, then sort and drop repeats within each row.
    const std::vector<uint32_t>& vc = level.vertex_cluster;
    std::vector<uint32_t> offsets(clusters + 1, 0);
    for_each_edge(mesh, [&](uint32_t a, uint32_t b) {
        if (vc[a] != vc[b]) {
            ++offsets[vc[a] + 1];
            ++offsets[vc[b] + 1];
        }
    });
    for (uint32_t k = 0; k < clusters; ++k) offsets[k + 1] += offsets[k];
    std::vector<uint32_t> fill(offsets.begin(), offsets.end() - 1), adj(offsets.back());
    for_each_edge(mesh, [&](uint32_t a, uint32_t b) {
        if (vc[a] != vc[b]) {
            adj[fill[vc[a]]++] = vc[b];
            adj[fill[vc[b]]++] = vc[a];
        }
    });
    level.adj_offsets.assign(clusters + 1, 0);
    uint32_t out = 0;  // compacted in place: row k starts at or after where its old row did
    for (uint32_t k = 0; k < clusters; ++k) {
        auto first = adj.begin() + offsets[k], last = adj.begin() + offsets[k + 1];
        std::sort(first, last);
        last = std::unique(first, last);
        for (auto it = first; it != last; ++it) adj[out++] = *it;
        level.adj_offsets[k + 1] = out;
    }
    adj.resize(out);
    adj.shrink_to_fit();
    level.adj = std::move(adj);
    return level;
}

}  // namespace kappa
