#include "creases.h"

#include "edge_table.h"
#include "union_find.h"
#include "vertex_faces.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

glm::vec3 face_normal(const Mesh& mesh, const Face& f) {
    const glm::vec3 c = glm::cross(mesh.positions[f[1]] - mesh.positions[f[0]], mesh.positions[f[2]] - mesh.positions[f[0]]);
    const float len = glm::length(c);
    return len > 0 && std::isfinite(len) ? c / len : glm::vec3(0.0f);
}

std::vector<glm::uvec2> find_creases(const Mesh& mesh, float angle_deg) {
    std::vector<glm::uvec2> out;
    if (!(angle_deg > 0)) return out;
    const float cos_limit = std::cos(angle_deg * float(M_PI) / 180.0f);
    const EdgeTable edges = build_edge_table(mesh);
    for (size_t e = 0; e < edges.size(); ++e) {
        if (edges.face_count(e) != 2) continue;
        const glm::vec3 a = face_normal(mesh, mesh.faces[edges.halfedges[edges.first[e]] / 3]);
        const glm::vec3 b = face_normal(mesh, mesh.faces[edges.halfedges[edges.first[e] + 1] / 3]);
        if (a == glm::vec3(0.0f) || b == glm::vec3(0.0f)) continue;  // degenerate faces have no angle
        if (glm::dot(a, b) < cos_limit) out.push_back(edges.ends[e]);
    }
    return out;
}

float auto_crease_angle(const Mesh& mesh) {
    const EdgeTable edges = build_edge_table(mesh);
    const float cos_flat = std::cos(0.5f * float(M_PI) / 180.0f);
    const float cos_sharp = std::cos(kAutoCreaseAngle * float(M_PI) / 180.0f);
    size_t interior = 0, between = 0;
    for (size_t e = 0; e < edges.size(); ++e) {
        if (edges.face_count(e) != 2) continue;
        const glm::vec3 a = face_normal(mesh, mesh.faces[edges.halfedges[edges.first[e]] / 3]);
        const glm::vec3 b = face_normal(mesh, mesh.faces[edges.halfedges[edges.first[e] + 1] / 3]);
        if (a == glm::vec3(0.0f) || b == glm::vec3(0.0f)) continue;
        ++interior;
        const float d = glm::dot(a, b);
        between += d < cos_flat && d >= cos_sharp;
    }
    return interior > 0 && 2 * between <= interior ? kAutoCreaseAngle : 0.0f;
}

SplitMesh split_at_creases(Mesh mesh, const std::vector<glm::uvec2>& creases) {
    SplitMesh out;
    const size_t nv = mesh.vertex_count();
    out.original.resize(nv);
    for (size_t v = 0; v < nv; ++v) out.original[v] = uint32_t(v);
    if (creases.empty()) {  // most scans: no copy
        out.mesh = std::move(mesh);
        return out;
    }
    out.mesh = mesh;  // split in place below, reading the input's faces

    std::vector<uint64_t> crease_keys;
    crease_keys.reserve(creases.size());
    for (const auto& c : creases) crease_keys.push_back(uint64_t(std::min(c.x, c.y)) << 32 | std::max(c.x, c.y));
    std::sort(crease_keys.begin(), crease_keys.end());
    auto is_crease = [&](uint32_t a, uint32_t b) {
        const uint64_t key = uint64_t(std::min(a, b)) << 32 | std::max(a, b);
        return std::binary_search(crease_keys.begin(), crease_keys.end(), key);
    };
    std::vector<uint8_t> on_crease(nv, 0);
    for (const auto& c : creases) on_crease[c.x] = on_crease[c.y] = 1;

    // Around each crease vertex: faces joined across its non-crease edges.
    const VertexFaces vf = build_vertex_faces(mesh);
    for (size_t v = 0; v < nv; ++v) {
        if (!on_crease[v]) continue;
        const uint32_t begin = vf.begin(v), n = vf.end(v) - begin;
        UnionFind sides(n);
        for (uint32_t i = 0; i < n; ++i)
            for (uint32_t j = i + 1; j < n; ++j) {
                const Face& fi = mesh.faces[vf.corners[begin + i] / 3];
                const Face& fj = mesh.faces[vf.corners[begin + j] / 3];
                // The other two corners of each face; a shared one is a shared edge at v.
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b)
                        if (fi[a] != v && fi[a] == fj[b] && !is_crease(uint32_t(v), fi[a])) sides.unite(i, j);
            }
        std::vector<uint32_t> copy_of_root(n, UINT32_MAX);
        bool first = true;
        for (uint32_t i = 0; i < n; ++i) {  // corners in face order: deterministic numbering
            const uint32_t root = sides.find(i);
            if (copy_of_root[root] == UINT32_MAX) {
                if (first) {
                    copy_of_root[root] = uint32_t(v);
                    first = false;
                } else {
                    copy_of_root[root] = uint32_t(out.mesh.positions.size());
                    out.mesh.positions.push_back(mesh.positions[v]);
                    out.original.push_back(uint32_t(v));
                }
            }
            const uint32_t corner = vf.corners[begin + i];
            out.mesh.faces[corner / 3][corner % 3] = copy_of_root[root];
        }
    }

    // The creases in the split numbering (the first face's copy) and their faces.
    const EdgeTable edges = build_edge_table(mesh);
    for (size_t e = 0; e < edges.size(); ++e) {
        if (edges.face_count(e) != 2 || !is_crease(edges.ends[e].x, edges.ends[e].y)) continue;
        const uint32_t h0 = edges.halfedges[edges.first[e]], h1 = edges.halfedges[edges.first[e] + 1];
        const Face& f = out.mesh.faces[h0 / 3];
        out.creases.push_back({f[h0 % 3], f[(h0 % 3 + 1) % 3]});
        out.crease_faces.push_back({h0 / 3, h1 / 3});
    }
    return out;
}

}  // namespace kappa
