// The one-pass crease search (geometry/mesh/edge_bends.h) and the split that
// needs no edge table (creases.cpp) against the edge-table versions they
// replaced, kept here as the reference: the same creases in the same order,
// the same automatic angle, the same split mesh, on CAD parts, smooth and
// scanned meshes, and meshes with degenerate, repeated and non-manifold faces.
#include "test_support.h"

#include "geometry/io/mesh_io.h"
#include "geometry/mesh/creases.h"
#include "geometry/mesh/edge_table.h"
#include "geometry/mesh/primitives.h"
#include "geometry/mesh/union_find.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include "test_shapes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace kappa;

namespace {

// The edge-table implementations as they were (issue 30 before item 3).
std::vector<glm::uvec2> reference_find_creases(const Mesh& mesh, float angle_deg) {
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

float reference_auto_crease_angle(const Mesh& mesh) {
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

SplitMesh reference_split(Mesh mesh, const std::vector<glm::uvec2>& creases) {
    SplitMesh out;
    const size_t nv = mesh.vertex_count();
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
                    out.copied_from.push_back(uint32_t(v));
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

// A mesh that is hard to get right: the cube with a duplicated face, a face
// repeating a vertex, a zero-area face, a fin making an edge non-manifold,
// and a bowtie vertex.
Mesh awkward_mesh() {
    Mesh m = test::unit_cube();
    m.faces.push_back(m.faces[0]);  // edge used three times, twice by equal faces
    const uint32_t a = m.faces[3][0], b = m.faces[3][1];
    m.faces.push_back({a, a, b});   // repeats a vertex: not a valid face
    const uint32_t mid = uint32_t(m.positions.size());
    m.positions.push_back(0.5f * (m.positions[a] + m.positions[b]));
    m.faces.push_back({a, b, mid});  // zero area: no normal
    const uint32_t fin = uint32_t(m.positions.size());
    m.positions.push_back(m.positions[a] + glm::vec3(0.3f, 0.7f, 1.9f));
    m.faces.push_back({m.faces[5][0], m.faces[5][1], fin});  // a fin on an edge
    const uint32_t p = uint32_t(m.positions.size());
    m.positions.push_back(m.positions[a] + glm::vec3(2, 0, 0));
    m.positions.push_back(m.positions[a] + glm::vec3(2, 1, 0));
    m.faces.push_back({a, p, p + 1});  // a second fan at a: a bowtie
    return m;
}

// Shared meshes with their vertices jittered (more bends between flat and sharp).
Mesh jittered(Mesh m, float amount, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-amount, amount);
    for (glm::vec3& p : m.positions) p += glm::vec3(u(rng), u(rng), u(rng));
    return m;
}

void check_same(const Mesh& m, float angle) {
    INFO("angle " << angle);
    const std::vector<glm::uvec2> creases = find_creases(m, angle);
    CHECK(creases == reference_find_creases(m, angle));
    const SplitMesh split = split_at_creases(m, creases), expected = reference_split(m, creases);
    CHECK(split.mesh.positions == expected.mesh.positions);
    CHECK(split.mesh.faces == expected.mesh.faces);
    CHECK(split.copied_from == expected.copied_from);
    CHECK(split.creases == expected.creases);
    CHECK(split.crease_faces == expected.crease_faces);
    // With the vertex-face rows given: the same split, and the rows made the split mesh's.
    VertexFaces vf = build_vertex_faces(m);
    CHECK(resolve_creases(m, vf, angle).creases == creases);
    const SplitMesh with_rows = split_at_creases(m, creases, &vf);
    CHECK(with_rows.mesh.faces == expected.mesh.faces);
    CHECK(with_rows.creases == expected.creases);
    const VertexFaces rebuilt = build_vertex_faces(with_rows.mesh);
    CHECK(vf.offsets == rebuilt.offsets);
    CHECK(vf.corners == rebuilt.corners);
}

}  // namespace

TEST_CASE("Creases: the one-pass search and split equal the edge-table ones", "[creases]") {
    std::vector<std::pair<std::string, Mesh>> meshes;
    meshes.push_back({"cube", test::unit_cube()});
    meshes.push_back({"awkward", awkward_mesh()});
    meshes.push_back({"icosphere", make_icosphere(1, 3)});
    meshes.push_back({"fandisk", load_mesh(test::shared_mesh("fandisk.obj"))});
    meshes.push_back({"bunny", load_mesh(test::shared_mesh("bunny.ply"))});
    meshes.push_back({"jittered fandisk", jittered(load_mesh(test::shared_mesh("fandisk.obj")), 0.01f, 7)});
    for (const auto& [name, m] : meshes) {
        INFO(name);
        CHECK(auto_crease_angle(m) == reference_auto_crease_angle(m));
        for (const float angle : {kAutoCreaseAngle, 10.0f, 60.0f, 0.0f}) check_same(m, angle);
        // The whole setting at once, as drawing resolves it.
        const ResolvedCreases resolved = resolve_creases(m, -1);
        CHECK(resolved.angle == reference_auto_crease_angle(m));
        CHECK(resolved.creases == reference_find_creases(m, resolved.angle));
        CHECK(resolve_creases(m, 25).creases == reference_find_creases(m, 25));
        CHECK(resolve_creases(m, 0).creases.empty());
    }
}

TEST_CASE("Creases: the same whatever the thread count", "[creases]") {
    const Mesh m = jittered(load_mesh(test::shared_mesh("fandisk.obj")), 0.005f, 3);
    set_thread_count(1);
    const std::vector<glm::uvec2> one = find_creases(m, 20);
    const SplitMesh split_one = split_at_creases(m, one);
    set_thread_count(0);
    CHECK(find_creases(m, 20) == one);
    const SplitMesh split = split_at_creases(m, one);
    CHECK(split.mesh.faces == split_one.mesh.faces);
    CHECK(split.creases == split_one.creases);
}
