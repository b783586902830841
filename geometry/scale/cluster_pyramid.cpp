#include "cluster_pyramid.h"

#include "geometry/union_find.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

// What is grouped into the clusters of one level: mesh vertices for the
// first level, the clusters of the level below for the others.
struct Items {
    std::vector<glm::ivec3> key;   // grid cell
    std::vector<float> area;
    std::vector<glm::dvec3> area_position;  // area x position (sums for clusters)
    std::vector<glm::dvec3> position;       // plain position sums, for zero-area items
    std::vector<uint32_t> count;            // vertices in the item
    std::vector<glm::vec3> normal_sum;
};

struct Grouping {
    ClusterLevel level;
    Items clusters;  // the new clusters as items of the next level (keys not yet halved)
    std::vector<uint32_t> item_cluster;
};

// Connected pieces of the items inside each cell, joined along `for_each_edge`
// (calls fn(a, b) for every edge between items a and b).
template <typename ForEachEdge>
Grouping group_items(const Items& items, ForEachEdge for_each_edge) {
    const size_t n = items.key.size();
    UnionFind uf(n);
    for_each_edge([&](uint32_t a, uint32_t b) {
        if (items.key[a] == items.key[b]) uf.unite(a, b);
    });

    Grouping g;
    g.item_cluster.assign(n, UINT32_MAX);
    std::vector<uint32_t> root_cluster(n, UINT32_MAX);
    uint32_t clusters = 0;
    for (size_t i = 0; i < n; ++i) {  // numbered by first item: deterministic
        const uint32_t r = uf.find(uint32_t(i));
        if (root_cluster[r] == UINT32_MAX) root_cluster[r] = clusters++;
        g.item_cluster[i] = root_cluster[r];
    }

    Items& c = g.clusters;
    c.key.resize(clusters);
    c.area.assign(clusters, 0.0f);
    c.area_position.assign(clusters, glm::dvec3(0.0));
    c.position.assign(clusters, glm::dvec3(0.0));
    c.count.assign(clusters, 0);
    c.normal_sum.assign(clusters, glm::vec3(0.0f));
    for (size_t i = 0; i < n; ++i) {
        const uint32_t k = g.item_cluster[i];
        c.key[k] = items.key[i];
        c.area[k] += items.area[i];
        c.area_position[k] += items.area_position[i];
        c.position[k] += items.position[i];
        c.count[k] += items.count[i];
        c.normal_sum[k] += items.normal_sum[i];
    }

    ClusterLevel& level = g.level;
    level.area = c.area;
    level.normal_sum = c.normal_sum;
    level.centroid.resize(clusters);
    for (uint32_t k = 0; k < clusters; ++k)
        level.centroid[k] = c.area[k] > 0 ? glm::vec3(c.area_position[k] / double(c.area[k]))
                                          : glm::vec3(c.position[k] / double(std::max(c.count[k], 1u)));

    // Adjacency: count, fill, then sort and drop repeats within each row.
    std::vector<uint32_t> offsets(clusters + 1, 0);
    for_each_edge([&](uint32_t a, uint32_t b) {
        const uint32_t ca = g.item_cluster[a], cb = g.item_cluster[b];
        if (ca != cb) {
            ++offsets[ca + 1];
            ++offsets[cb + 1];
        }
    });
    for (uint32_t k = 0; k < clusters; ++k) offsets[k + 1] += offsets[k];
    std::vector<uint32_t> fill(offsets.begin(), offsets.end() - 1), adj(offsets.back());
    for_each_edge([&](uint32_t a, uint32_t b) {
        const uint32_t ca = g.item_cluster[a], cb = g.item_cluster[b];
        if (ca != cb) {
            adj[fill[ca]++] = cb;
            adj[fill[cb]++] = ca;
        }
    });
    level.adj_offsets.assign(clusters + 1, 0);
    level.adj.reserve(adj.size() / 3);
    for (uint32_t k = 0; k < clusters; ++k) {
        auto first = adj.begin() + offsets[k], last = adj.begin() + offsets[k + 1];
        std::sort(first, last);
        last = std::unique(first, last);
        level.adj.insert(level.adj.end(), first, last);
        level.adj_offsets[k + 1] = uint32_t(level.adj.size());
    }
    return g;
}

}  // namespace

ClusterPyramid build_cluster_pyramid(const Mesh& mesh, const std::vector<float>& point_areas,
                                     const std::vector<glm::vec3>& normals, float first_cell, float max_cell) {
    ClusterPyramid pyramid;
    const size_t nv = mesh.vertex_count();
    if (nv == 0 || !(first_cell > 0) || !std::isfinite(first_cell)) return pyramid;

    glm::vec3 lo = mesh.positions[0];
    for (const auto& p : mesh.positions) lo = glm::min(lo, p);

    Items items;
    items.key.resize(nv);
    items.area = point_areas;
    items.area_position.resize(nv);
    items.position.resize(nv);
    items.count.assign(nv, 1);
    items.normal_sum.resize(nv);
    for (size_t v = 0; v < nv; ++v) {
        const glm::vec3 p = mesh.positions[v];
        items.key[v] = glm::ivec3(glm::floor((p - lo) / first_cell));
        items.area_position[v] = double(point_areas[v]) * glm::dvec3(p);
        items.position[v] = glm::dvec3(p);
        items.normal_sum[v] = point_areas[v] * normals[v];
    }

    // First level: vertices joined along mesh edges.
    Grouping g = group_items(items, [&](auto&& fn) {
        for (const Face& f : mesh.faces)
            for (int e = 0; e < 3; ++e) {
                const uint32_t a = f[e], b = f[(e + 1) % 3];
                if (a != b) fn(a, b);
            }
    });
    g.level.cell = first_cell;
    g.level.vertex_cluster = std::move(g.item_cluster);

    for (;;) {
        pyramid.levels.push_back(std::move(g.level));
        const ClusterLevel& below = pyramid.levels.back();
        const float cell = below.cell * 2.0f;
        if (cell > max_cell || below.size() <= 8) break;
        Items next = std::move(g.clusters);
        for (auto& k : next.key) k = k / 2;  // keys are >= 0: division is the floor
        g = group_items(next, [&](auto&& fn) {
            for (uint32_t c = 0; c < below.size(); ++c)
                for (uint32_t k = below.adj_offsets[c]; k < below.adj_offsets[c + 1]; ++k)
                    if (below.adj[k] > c) fn(c, below.adj[k]);
        });
        g.level.cell = cell;
        g.level.vertex_cluster.resize(nv);
        for (size_t v = 0; v < nv; ++v) g.level.vertex_cluster[v] = g.item_cluster[below.vertex_cluster[v]];
    }
    return pyramid;
}

}  // namespace kappa
