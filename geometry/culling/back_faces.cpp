#include "back_faces.h"

#include "geometry/mesh/edge_table.h"  // is_valid_face, sort_short_run
#include "geometry/mesh/orientation.h"
#include "geometry/mesh/union_find.h"
#include "geometry/parallel/parallel.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <stdexcept>

namespace kappa {

namespace {

// The half-edges of v's faces that join v to a larger vertex w, as keys w << 1 | out (out: the half-edge
// runs v -> w), sorted. Faces without three distinct vertices have no edges (edge_table.h). Seen from
// its smaller end, every edge is listed once per face using it.
void edges_to_larger(const Mesh& mesh, const VertexFaces& vf, uint32_t v, std::vector<uint64_t>& keys) {
    keys.clear();
    const size_t nv = mesh.vertex_count();
    for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
        const uint32_t c = vf.corners[k];
        const Face& f = mesh.faces[c / 3];
        if (!is_valid_face(f, nv)) continue;
        const uint32_t next = f[(c % 3 + 1) % 3], prev = f[(c % 3 + 2) % 3];
        if (next > v) keys.push_back(uint64_t(next) << 1 | 1);
        if (prev > v) keys.push_back(uint64_t(prev) << 1);
    }
    sort_short_run(keys.data(), keys.data() + keys.size());
}

// A row's faces lie anywhere in memory: asking for a later vertex's while working on this one's
// overlaps their cache misses (about 1.4x on the 17.8M-face subdivided bunny).
void prefetch_faces(const Mesh& mesh, const VertexFaces& vf, uint32_t v) {
    for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) __builtin_prefetch(&mesh.faces[vf.corners[k] / 3]);
}

// Whether keys[i]'s edge is used by one face alone (an open edge).
bool is_open(const std::vector<uint64_t>& keys, size_t i) {
    const uint64_t w = keys[i] >> 1;
    return (i == 0 || keys[i - 1] >> 1 != w) && (i + 1 == keys.size() || keys[i + 1] >> 1 != w);
}

}  // namespace

BackFaceVisibility back_face_visibility(const Mesh& mesh) {
    return back_face_visibility(mesh, build_vertex_faces(mesh), is_outside_out(mesh));
}

BackFaceVisibility back_face_visibility(const Mesh& mesh, const VertexFaces& vf, bool outside_out) {
    BackFaceVisibility out;
    const size_t nv = mesh.vertex_count();
    if (vf.offsets.size() != nv + 1)
        throw std::invalid_argument("back_face_visibility: vertex-face rows of another mesh");
    if (!outside_out) return out;
    // Every edge used at most once in each direction: two faces using it in one direction are a
    // wrong winding, three or more faces are two in one direction. An edge used once is open.
    // Checked at each edge's smaller end, the vertices in parallel; a vertex with an open edge
    // to a larger one is marked, for the holes below.
    std::atomic<bool> consistent = true;
    std::vector<uint8_t> starts_open(nv, 0);
    parallel_for_chunks(nv, [&](size_t first, size_t last) {
        std::vector<uint64_t> keys;
        for (size_t v = first; v < last && consistent.load(std::memory_order_relaxed); ++v) {
            if (v + 8 < last) prefetch_faces(mesh, vf, uint32_t(v + 8));
            edges_to_larger(mesh, vf, uint32_t(v), keys);
            for (size_t i = 0; i < keys.size(); ++i) {
                if (i + 1 < keys.size() && keys[i + 1] == keys[i]) consistent = false;
                if (is_open(keys, i)) starts_open[v] = 1;
            }
        }
    });
    if (!consistent) return out;
    out.cullable = true;
    // The holes: the open edges joined into boundary components (few vertices, one thread).
    std::vector<glm::uvec2> open_edges;
    std::vector<uint64_t> keys;
    for (uint32_t v = 0; v < nv; ++v) {
        if (!starts_open[v]) continue;
        edges_to_larger(mesh, vf, v, keys);
        for (size_t i = 0; i < keys.size(); ++i)
            if (is_open(keys, i)) open_edges.push_back({v, uint32_t(keys[i] >> 1)});
    }
    std::vector<uint32_t> ends;  // the open edges' vertices, in increasing order
    for (const glm::uvec2& e : open_edges) ends.push_back(e.x), ends.push_back(e.y);
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    const auto slot = [&](uint32_t v) {
        return uint32_t(std::lower_bound(ends.begin(), ends.end(), v) - ends.begin());
    };
    UnionFind boundary(ends.size());
    for (const glm::uvec2& e : open_edges) boundary.unite(slot(e.x), slot(e.y));
    std::map<uint32_t, size_t> hole_of_root;  // in order of each hole's smallest vertex: deterministic
    for (uint32_t i = 0; i < ends.size(); ++i) {
        const auto [it, added] = hole_of_root.try_emplace(boundary.find(i), out.holes.size());
        if (added) out.holes.emplace_back();
        out.holes[it->second].push_back(mesh.positions[ends[i]]);
    }
    return out;
}

}  // namespace kappa
