#include "back_faces.h"

#include "geometry/mesh/edge_table.h"
#include "geometry/mesh/orientation.h"
#include "geometry/mesh/union_find.h"

#include <map>

namespace kappa {

BackFaceVisibility back_face_visibility(const Mesh& mesh) {
    BackFaceVisibility out;
    const EdgeTable edges = build_edge_table(mesh);
    UnionFind boundary(mesh.vertex_count());
    std::vector<uint8_t> on_boundary(mesh.vertex_count(), 0);
    for (size_t e = 0; e < edges.size(); ++e) {
        const uint32_t n = edges.face_count(e);
        if (n > 2) return out;  // non-manifold
        if (n == 1) {
            boundary.unite(edges.ends[e].x, edges.ends[e].y);
            on_boundary[edges.ends[e].x] = on_boundary[edges.ends[e].y] = 1;
            continue;
        }
        // Two faces: their half-edges must run opposite ways.
        auto forward = [&](uint32_t h) {
            const Face& f = mesh.faces[h / 3];
            return f[h % 3] < f[(h % 3 + 1) % 3];
        };
        if (forward(edges.halfedges[edges.first[e]]) == forward(edges.halfedges[edges.first[e] + 1])) return out;
    }
    if (!is_outside_out(mesh)) return out;
    out.cullable = true;
    std::map<uint32_t, size_t> hole_of_root;  // in order of each hole's smallest vertex: deterministic
    for (uint32_t v = 0; v < mesh.vertex_count(); ++v) {
        if (!on_boundary[v]) continue;
        const auto [it, added] = hole_of_root.try_emplace(boundary.find(v), out.holes.size());
        if (added) out.holes.emplace_back();
        out.holes[it->second].push_back(mesh.positions[v]);
    }
    return out;
}

}  // namespace kappa
