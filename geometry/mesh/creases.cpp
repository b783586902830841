#include "creases.h"

#include "crease_vote.h"
#include "edge_bends.h"
#include "face_survey.h"
#include "edge_table.h"
#include "union_find.h"
#include "vertex_faces.h"

#include "geometry/io/prefault.h"
#include "geometry/parallel/parallel.h"
#include "geometry/parallel/shift_down.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstring>
#include <cmath>

namespace kappa {

std::vector<glm::uvec2> creases_around(const Mesh& mesh, const VertexFaces& vf, float angle_deg,
                                      const std::vector<uint32_t>& candidates) {
    if (!(angle_deg > 0)) return {};
    // Both passes are exact; around many candidates the whole one is the cheaper.
    if (8 * candidates.size() > mesh.vertex_count()) return measure_edge_bends(mesh, vf, angle_deg).creases;
    return measure_edge_bends_at(mesh, vf, angle_deg, candidates).creases;
}

std::vector<glm::uvec2> find_creases(const Mesh& mesh, float angle_deg) {
    if (!(angle_deg > 0)) return {};
    const VertexFaces vf = build_vertex_faces(mesh);
    return creases_around(mesh, vf, angle_deg, crease_candidates(mesh, vf, angle_deg));
}

float auto_crease_angle(const Mesh& mesh) { return resolve_creases(mesh, build_vertex_faces(mesh), -1, false).angle; }

std::optional<float> sampled_crease_angle(const Mesh& mesh, const VertexFaces& vf, float setting) {
    if (setting >= 0) return setting;
    const CreaseVote vote = sampled_crease_vote(mesh, vf);
    if (vote == CreaseVote::Unclear) return std::nullopt;
    return vote == CreaseVote::On ? kAutoCreaseAngle : 0.0f;
}

ResolvedCreases resolve_creases(const Mesh& mesh, float setting) {
    if (setting == 0) return {};
    return resolve_creases(mesh, build_vertex_faces(mesh), setting);
}

ResolvedCreases resolve_creases(const Mesh& mesh, const VertexFaces& vf, float setting, bool find) {
    ResolvedCreases out;
    if (setting == 0) return out;
    if (const std::optional<float> angle = sampled_crease_angle(mesh, vf, setting)) {
        out.angle = *angle;
        if (find) out.creases = creases_around(mesh, vf, out.angle, crease_candidates(mesh, vf, out.angle));
        return out;
    }
    // Auto, and the sample cannot tell: every edge counts.
    EdgeBends bends = measure_edge_bends(mesh, vf, find ? kAutoCreaseAngle : 0);
    out.angle = auto_creases_on(bends) ? kAutoCreaseAngle : 0.0f;
    if (out.angle > 0) out.creases = std::move(bends.creases);
    return out;
}

namespace {

// The corners at the given vertices (sorted) as (vertex << 32 | corner),
// sorted: each vertex's corners in face order, as in its row of
// vertex_faces.h. One pass over the faces, in blocks whose results are joined
// in order.
std::vector<uint64_t> corners_at(const Mesh& mesh, const std::vector<uint32_t>& vertices) {
    std::vector<uint8_t> marked(mesh.vertex_count() + 1, 0);  // + 1: corners past the last vertex
    for (const uint32_t v : vertices) marked[v] = 1;
    auto is_marked = [&](uint32_t v) { return marked[std::min<size_t>(v, mesh.vertex_count())] != 0; };
    constexpr size_t kBlock = 65536;
    const size_t nf = mesh.face_count(), blocks = (nf + kBlock - 1) / kBlock;
    std::vector<std::vector<uint64_t>> found(blocks);
    parallel_for_chunks(
        blocks,
        [&](size_t first, size_t last) {
            for (size_t b = first; b < last; ++b)
                for (size_t f = b * kBlock; f < std::min(nf, (b + 1) * kBlock); ++f)
                    for (uint32_t i = 0; i < 3; ++i)
                        if (const uint32_t v = mesh.faces[f][i]; is_marked(v))
                            found[b].push_back(uint64_t(v) << 32 | (3 * f + i));
        },
        1);
    std::vector<uint64_t> all;
    for (const auto& b : found) all.insert(all.end(), b.begin(), b.end());
    std::sort(all.begin(), all.end());
    return all;
}

// Makes `vf` the rows of the split mesh: `moves` (corner, copy) take
// corners out of their vertex's row (compacting the rows in place) into the
// rows of the copies, vertices first_copy on; copied_from[copy - first_copy]
// is the vertex a copy was made from.
void move_corners(VertexFaces& vf, std::vector<std::pair<uint32_t, uint32_t>> moves,
                  const std::vector<uint32_t>& copied_from, size_t first_copy) {
    if (moves.empty()) return;
    const size_t vertex_count = first_copy + copied_from.size();
    std::vector<uint32_t> moved;  // sorted corners
    for (const auto& m : moves) moved.push_back(m.first);
    std::sort(moved.begin(), moved.end());
    auto is_moved = [&](uint32_t c) { return std::binary_search(moved.begin(), moved.end(), c); };
    std::vector<uint32_t> losing;  // the vertices that lose corners, sorted
    for (const auto& m : moves) losing.push_back(copied_from[m.second - first_copy]);
    std::sort(losing.begin(), losing.end());
    losing.erase(std::unique(losing.begin(), losing.end()), losing.end());
    // Rows before the first of them stay where they are. Each losing row keeps its other corners; the
    // rows between two losing ones shift down by the corners lost so far, in one move.
    uint32_t lost = 0;
    auto shift_rows = [&](size_t first, size_t last) {  // [first, last): untouched rows
        if (lost == 0 || first >= last) return;
        const uint32_t begin = vf.offsets[first], end = vf.offsets[last];
        shift_down(vf.corners.data(), begin, end, lost);
        parallel_for_chunks(last - first, [&](size_t a, size_t b) {
            for (size_t v = first + a; v < first + b; ++v) vf.offsets[v] -= lost;
        }, size_t(1) << 20);
    };
    size_t next_row = losing.front();
    for (const uint32_t v : losing) {
        shift_rows(next_row, v);
        const uint32_t begin = vf.offsets[v], end = vf.offsets[v + 1];
        uint32_t kept = begin - lost;
        vf.offsets[v] = kept;
        for (uint32_t k = begin; k < end; ++k)
            if (!is_moved(vf.corners[k])) vf.corners[kept++] = vf.corners[k];
        lost = end - kept;
        next_row = v + 1;
    }
    shift_rows(next_row, first_copy);
    uint32_t out = vf.offsets[first_copy] - lost;
    // The copies' rows: corners in increasing order, as build_vertex_faces gives.
    std::sort(moves.begin(), moves.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second < b.second : a.first < b.first;
    });
    vf.offsets.resize(vertex_count + 1);
    size_t m = 0;
    for (size_t copy = first_copy; copy < vertex_count; ++copy) {
        vf.offsets[copy] = out;
        for (; m < moves.size() && moves[m].second == copy; ++m) vf.corners[out++] = moves[m].first;
    }
    vf.offsets[vertex_count] = out;
}

// As corners_at, from the vertex-face rows.
std::vector<uint64_t> crease_corners(const VertexFaces& vf, const std::vector<uint32_t>& vertices) {
    std::vector<uint64_t> all;
    for (const uint32_t v : vertices)
        for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) all.push_back(uint64_t(v) << 32 | vf.corners[k]);
    return all;
}

}  // namespace

SplitMesh split_at_creases(Mesh mesh, const std::vector<glm::uvec2>& creases, VertexFaces* vf) {
    SplitMesh out;
    const size_t nv = mesh.vertex_count();
    if (creases.empty()) {  // most scans: no copy
        out.mesh = std::move(mesh);
        return out;
    }

    std::vector<uint64_t> crease_keys;
    crease_keys.reserve(creases.size());
    for (const auto& c : creases)
        if (c.x != c.y && c.x < nv && c.y < nv)
            crease_keys.push_back(uint64_t(std::min(c.x, c.y)) << 32 | std::max(c.x, c.y));
    std::sort(crease_keys.begin(), crease_keys.end());
    crease_keys.erase(std::unique(crease_keys.begin(), crease_keys.end()), crease_keys.end());
    auto is_crease = [&](uint32_t a, uint32_t b) {
        const uint64_t key = uint64_t(std::min(a, b)) << 32 | std::max(a, b);
        return std::binary_search(crease_keys.begin(), crease_keys.end(), key);
    };
    std::vector<uint32_t> on_crease;  // the creases' vertices, sorted
    for (const uint64_t key : crease_keys) on_crease.push_back(uint32_t(key >> 32)), on_crease.push_back(uint32_t(key));
    std::sort(on_crease.begin(), on_crease.end());
    on_crease.erase(std::unique(on_crease.begin(), on_crease.end()), on_crease.end());

    // Around each crease vertex: faces joined across its non-crease edges.
    // The faces are read as they came in; the new corner numbers are kept
    // aside (moves) and written once every vertex is done.
    const std::vector<uint64_t> fans = vf ? crease_corners(*vf, on_crease) : corners_at(mesh, on_crease);
    auto fan_of = [&](uint32_t v) {  // [begin, end) in fans
        const auto lo = std::lower_bound(fans.begin(), fans.end(), uint64_t(v) << 32);
        const auto hi = std::lower_bound(lo, fans.end(), uint64_t(v + 1) << 32);
        return std::make_pair(size_t(lo - fans.begin()), size_t(hi - fans.begin()));
    };
    std::vector<std::pair<uint32_t, uint32_t>> moves;  // (corner, its vertex's copy)
    for (size_t begin = 0; begin < fans.size();) {
        const uint32_t v = uint32_t(fans[begin] >> 32);
        const uint32_t n = uint32_t(fan_of(v).second - begin);
        auto face_of = [&](uint32_t i) -> const Face& { return mesh.faces[uint32_t(fans[begin + i]) / 3]; };
        UnionFind sides(n);
        for (uint32_t i = 0; i < n; ++i)
            for (uint32_t j = i + 1; j < n; ++j) {
                const Face& fi = face_of(i);
                const Face& fj = face_of(j);
                // The other two corners of each face; a shared one is a shared edge at v.
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b)
                        if (fi[a] != v && fi[a] == fj[b] && !is_crease(v, fi[a])) sides.unite(i, j);
            }
        std::vector<uint32_t> copy_of_root(n, UINT32_MAX);
        bool first = true;
        for (uint32_t i = 0; i < n; ++i) {  // corners in face order: deterministic numbering
            const uint32_t root = sides.find(i);
            if (copy_of_root[root] == UINT32_MAX) {
                if (first) {
                    copy_of_root[root] = v;
                    first = false;
                } else {
                    copy_of_root[root] = uint32_t(nv + out.copied_from.size());
                    out.copied_from.push_back(v);
                }
            }
            if (copy_of_root[root] != v) moves.push_back({uint32_t(fans[begin + i]), copy_of_root[root]});
        }
        begin += n;
    }

    // The creases in the split numbering (the first face's copy) and their
    // faces: the edges between exactly two valid faces, found around their
    // smaller vertex, in sorted order (as an edge table lists them).
    for (const uint64_t key : crease_keys) {
        const uint32_t v0 = uint32_t(key >> 32), v1 = uint32_t(key);
        const auto [lo, hi] = fan_of(v0);
        uint32_t faces[2], count = 0;
        for (size_t k = lo; k < hi; ++k) {
            const uint32_t f = uint32_t(fans[k]) / 3;
            const Face& face = mesh.faces[f];
            if (is_valid_face(face, nv) && (face[0] == v1 || face[1] == v1 || face[2] == v1) && count++ < 2)
                faces[count - 1] = f;
        }
        if (count != 2) continue;
        const Face& first_face = mesh.faces[faces[0]];
        auto on_edge = [&](int i) { return first_face[i % 3] == v0 || first_face[i % 3] == v1; };
        int i = 0;  // the first face's half-edge along the crease: i -> i + 1
        while (!(on_edge(i) && on_edge(i + 1))) ++i;
        out.creases.push_back({uint32_t(i), faces[0]});  // corner numbers for now: renumbered below
        out.crease_faces.push_back({faces[0], faces[1]});
    }

    out.mesh = std::move(mesh);
    io::reserve_prefaulted(out.mesh.positions, nv + out.copied_from.size());
    for (const uint32_t v : out.copied_from) out.mesh.positions.push_back(out.mesh.positions[v]);
    for (const auto& [corner, copy] : moves) out.mesh.faces[corner / 3][corner % 3] = copy;
    if (vf) move_corners(*vf, std::move(moves), out.copied_from, nv);
    for (glm::uvec2& c : out.creases) {
        const Face& f = out.mesh.faces[c.y];
        c = {f[c.x], f[(c.x + 1) % 3]};
    }
    return out;
}

}  // namespace kappa
