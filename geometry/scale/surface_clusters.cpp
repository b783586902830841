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
// Over the faces [first, last).
template <typename Fn>
void for_each_edge(const Mesh& mesh, size_t first, size_t last, Fn&& fn) {
    for (size_t f = first; f < last; ++f)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = mesh.faces[f][e], b = mesh.faces[f][(e + 1) % 3];
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

// for_each_edge over blocks of faces on the threads: fn must be safe to call from several at once.
template <typename Fn>
void for_each_edge_in_parallel(const Mesh& mesh, Fn&& fn) {
    parallel_for_chunks(mesh.face_count(), [&](size_t first, size_t last) { for_each_edge(mesh, first, last, fn); },
                        65536);
}

// Sorts distinct pairs: halves sorted on two threads, then merged.
void sort_in_parallel(std::vector<std::pair<uint64_t, uint32_t>>& v) {
    const size_t half = v.size() / 2;
    parallel_for(2, [&](size_t k) { std::sort(v.begin() + long(k * half), k ? v.end() : v.begin() + long(half)); }, 1);
    std::inplace_merge(v.begin(), v.begin() + long(half), v.end());
}

}  // namespace

ClusterLevel build_surface_clusters(const Mesh& mesh, const std::vector<float>& point_areas,
                                    const std::vector<glm::vec3>& normals, glm::vec3 origin, float cell) {
    ClusterLevel level;
    const size_t n = mesh.vertex_count();
    if (n == 0 || !(cell > 0) || !std::isfinite(cell)) return level;
    level.cell = cell;
    std::vector<glm::ivec3> key(n);
    parallel_for(n, [&](size_t v) { key[v] = glm::ivec3(glm::floor((mesh.positions[v] - origin) / cell)); });

    UnionFind uf(n);
    for_each_edge(mesh, 0, mesh.face_count(), [&](uint32_t a, uint32_t b) {
        if (key[a] == key[b]) uf.unite(a, b);
    });

    // Clusters numbered along a Z-order curve through their cells (pieces of one cell by
    // their first vertex): neighbours get near numbers, so the fits' visits of a cluster's
    // neighbours stay in the cache. Deterministic.
    // Each vertex's root and each root's first (least) vertex, on the threads; then the roots in that order.
    std::vector<uint32_t> root(n), first_vertex(n, UINT32_MAX);
    parallel_for(n, [&](size_t v) {
        const uint32_t r = root[v] = uf.root(uint32_t(v));
        uint32_t least = __atomic_load_n(&first_vertex[r], __ATOMIC_RELAXED);
        while (v < least && !__atomic_compare_exchange_n(&first_vertex[r], &least, uint32_t(v), true,
                                                         __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
        }
    });
    std::vector<std::pair<uint64_t, uint32_t>> order;  // (Z-order code of the cell, first vertex) per cluster
    for (size_t r = 0; r < n; ++r)
        if (first_vertex[r] != UINT32_MAX) order.push_back({z_order(key[first_vertex[r]]), first_vertex[r]});
    std::vector<glm::ivec3>().swap(key);
    const uint32_t clusters = uint32_t(order.size());
    sort_in_parallel(order);
    std::vector<uint32_t>& root_cluster = first_vertex;  // now each root's cluster
    parallel_for(clusters, [&](size_t k) { root_cluster[root[order[k].second]] = uint32_t(k); });
    std::vector<std::pair<uint64_t, uint32_t>>().swap(order);
    level.vertex_cluster.resize(n);
    parallel_for(n, [&](size_t v) { level.vertex_cluster[v] = root_cluster[root[v]]; });
    std::vector<uint32_t>().swap(root);
    std::vector<uint32_t>().swap(root_cluster);

    // Each cluster's sums over its vertices in vertex order, as one thread would make them: each
    // thread scans every vertex and sums those of its own range of clusters.
    level.area.assign(clusters, 0.0f);
    level.normal_sum.assign(clusters, glm::vec3(0.0f));
    std::vector<glm::vec3> area_position(clusters, glm::vec3(0.0f));
    level.centroid.assign(clusters, glm::vec3(0.0f));  // plain position sums first
    std::vector<uint32_t> count(clusters, 0);
    parallel_for_ranges(clusters, [&](size_t lo, size_t hi) {
        for (size_t v = 0; v < n; ++v) {
            const uint32_t k = level.vertex_cluster[v];
            if (k < lo || k >= hi) continue;
            const float a = point_areas[v];
            level.area[k] += a;
            area_position[k] += a * mesh.positions[v];
            level.normal_sum[k] += a * normals[v];
            level.centroid[k] += mesh.positions[v];
            ++count[k];
        }
    }, 4096);
    parallel_for(clusters, [&](size_t k) {
        level.centroid[k] = level.area[k] > 0 ? area_position[k] / level.area[k] : level.centroid[k] / float(count[k]);
    });

    // Adjacency: count, fill (on the threads, in whatever order they come), then sort and drop
    // repeats within each row: the rows are sets, the same whatever the threads did.
    const std::vector<uint32_t>& vc = level.vertex_cluster;
    std::vector<uint32_t> offsets(clusters + 1, 0);
    for_each_edge_in_parallel(mesh, [&](uint32_t a, uint32_t b) {
        if (vc[a] != vc[b]) {
            __atomic_fetch_add(&offsets[vc[a] + 1], 1u, __ATOMIC_RELAXED);
            __atomic_fetch_add(&offsets[vc[b] + 1], 1u, __ATOMIC_RELAXED);
        }
    });
    for (uint32_t k = 0; k < clusters; ++k) offsets[k + 1] += offsets[k];
    std::vector<uint32_t> fill(offsets.begin(), offsets.end() - 1), adj(offsets.back());
    for_each_edge_in_parallel(mesh, [&](uint32_t a, uint32_t b) {
        if (vc[a] != vc[b]) {
            adj[__atomic_fetch_add(&fill[vc[a]], 1u, __ATOMIC_RELAXED)] = vc[b];
            adj[__atomic_fetch_add(&fill[vc[b]], 1u, __ATOMIC_RELAXED)] = vc[a];
        }
    });
    std::vector<uint32_t>& kept = fill;  // each row's length without repeats
    parallel_for(clusters, [&](size_t k) {
        auto first = adj.begin() + offsets[k], last = adj.begin() + offsets[k + 1];
        std::sort(first, last);
        kept[k] = uint32_t(std::unique(first, last) - first);
    });
    level.adj_offsets.assign(clusters + 1, 0);
    for (uint32_t k = 0; k < clusters; ++k) level.adj_offsets[k + 1] = level.adj_offsets[k] + kept[k];
    level.adj.resize(level.adj_offsets.back());
    parallel_for(clusters, [&](size_t k) {
        std::copy_n(adj.begin() + offsets[k], kept[k], level.adj.begin() + level.adj_offsets[k]);
    });
    return level;
}
}  // namespace kappa
