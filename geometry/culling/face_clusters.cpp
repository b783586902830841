#include "face_clusters.h"

#include "geometry/mesh/vertex_faces.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace kappa {

namespace {

// vertex_order (new -> old: vertices in order of first use by faces[order[0]], faces[order[1]], ..., then
// the unused ones) and vertex_slot (its inverse).
void order_vertices_by_use(const Mesh& mesh, FaceClusters& out) {
    constexpr uint32_t none = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t>& new_id = out.vertex_slot;
    std::vector<uint32_t>& order = out.vertex_order;
    new_id.assign(mesh.vertex_count(), none);
    order.clear();
    order.reserve(mesh.vertex_count());
    for (uint32_t f : out.face_order)
        for (int j = 0; j < 3; ++j) {
            const uint32_t v = mesh.faces[f][j];
            if (new_id[v] == none) new_id[v] = uint32_t(order.size()), order.push_back(v);
        }
    for (uint32_t v = 0; v < new_id.size(); ++v)
        if (new_id[v] == none) new_id[v] = uint32_t(order.size()), order.push_back(v);
}

}  // namespace

FaceClusters cluster_faces(const Mesh& mesh, uint32_t max_faces, const VertexFaces* rows) {
    constexpr uint32_t none = std::numeric_limits<uint32_t>::max();
    const size_t nf = mesh.face_count();
    FaceClusters out;
    out.cluster_start.push_back(0);
    if (nf == 0) {
        order_vertices_by_use(mesh, out);
        return out;
    }
    max_faces = uint32_t(std::min<size_t>(std::max(max_faces, 1u), nf));
    out.face_order.resize(nf);
    out.cluster_start.reserve(nf / max_faces + 2);

    VertexFaces built;
    if (!rows) built = build_vertex_faces(mesh), rows = &built;
    if (rows->offsets.size() != mesh.vertex_count() + 1)
        throw std::invalid_argument("cluster_faces: vertex-face rows of another mesh");
    const VertexFaces& vf = *rows;
    std::vector<uint8_t> assigned(nf, 0);
    // Per vertex (side by side: they are wanted together): queued == c when it
    // is already in cluster c's queue (no reset per cluster); every face of its
    // fan before corner fan_next is assigned, so scans of the fan resume there
    // and a vertex with a huge fan (every face around one vertex) costs
    // O(its degree) in all, not that once per cluster.
    struct VertexState {
        uint32_t queued, fan_next;
    };
    std::vector<VertexState> state(mesh.vertex_count());
    for (size_t v = 0; v < state.size(); ++v) state[v] = {none, vf.offsets[v]};
    // The current cluster's vertices in breadth-first order (at most 3 per face).
    std::vector<uint32_t> queue(3 * size_t(max_faces));
    uint32_t taken = 0;  // faces assigned so far: out.face_order[0 .. taken)
    size_t cursor = 0;   // faces below it are all assigned
    uint32_t seed = 0;

    for (uint32_t c = 0;; ++c) {
        const uint32_t first = taken;
        size_t queued_count = 0;
        auto take = [&](uint32_t f) {
            assigned[f] = 1;
            out.face_order[taken++] = f;
            for (int j = 0; j < 3; ++j) {
                const uint32_t v = mesh.faces[f][j];
                if (state[v].queued != c) {
                    state[v].queued = c;
                    queue[queued_count++] = v;
                }
            }
        };
        take(seed);
        // Vertex rings around the seed: take the fan of each queued vertex in turn.
        size_t head = 0;
        for (; head < queued_count && taken - first < max_faces; ++head) {
            const uint32_t v = queue[head];
            uint32_t k = state[v].fan_next;
            for (; k < vf.end(v) && taken - first < max_faces; ++k) {
                const uint32_t f = vf.corners[k] / 3;
                if (!assigned[f]) take(f);
            }
            state[v].fan_next = k;
        }
        out.cluster_start.push_back(taken);
        if (taken == nf) break;

        // Next seed: the first unassigned face around the frontier (the queued
        // vertices whose fans were not all taken), else the next one in face order.
        seed = none;
        for (size_t q = head == 0 ? 0 : head - 1; q < queued_count && seed == none; ++q) {
            const uint32_t v = queue[q];
            uint32_t& k = state[v].fan_next;
            while (k < vf.end(v) && assigned[vf.corners[k] / 3]) ++k;
            if (k < vf.end(v)) seed = vf.corners[k] / 3;
        }
        if (seed == none) {
            while (assigned[cursor]) ++cursor;
            seed = uint32_t(cursor);
        }
    }
    order_vertices_by_use(mesh, out);
    return out;
}

}  // namespace kappa
