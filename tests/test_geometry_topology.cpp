// Edge table, boundaries, loops, components and Euler characteristic on
// meshes whose topology is known by construction.
#include <catch2/catch.hpp>

#include "test_support.h"

#include "geometry/mesh/edge_table.h"
#include "geometry/mesh/mesh_stats.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/mesh/primitives.h"
#include "geometry/curvature/face_geometry.h"
#include "geometry/curvature/vertex_flags.h"
#include "geometry/curvature/vertex_basics.h"

#include <algorithm>
#include <cmath>

using namespace kappa;

namespace {

Topology topology_of(const Mesh& m) { return analyze_topology(m, build_edge_table(m)); }

// The per-vertex flags the curvature pipeline computes (from one-rings only).
std::vector<uint8_t> vertex_flags_of(const Mesh& m) {
    const VertexFaces vf = build_vertex_faces(m);
    return compute_vertex_basics(vf, compute_face_geometry(m)).flags;
}

// Appends b to a (indices shifted).
Mesh merged(Mesh a, const Mesh& b, glm::vec3 offset) {
    const uint32_t base = uint32_t(a.positions.size());
    for (auto p : b.positions) a.positions.push_back(p + offset);
    for (auto f : b.faces) a.faces.push_back(f + glm::uvec3(base));
    return a;
}

// Removes the faces at the given indices.
Mesh without_faces(Mesh m, std::vector<size_t> drop) {
    std::sort(drop.rbegin(), drop.rend());
    for (size_t f : drop) m.faces.erase(m.faces.begin() + long(f));
    return m;
}

bool shares_vertex(const Face& a, const Face& b) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a[i] == b[j]) return true;
    return false;
}

}  // namespace

TEST_CASE("edge table lists each undirected edge once with its faces", "[topology]") {
    const Mesh m = make_icosphere(1.0f, 2);
    const EdgeTable t = build_edge_table(m);
    REQUIRE(t.size() == 3 * m.face_count() / 2);
    REQUIRE(t.first.size() == t.size() + 1);
    REQUIRE(t.halfedges.size() == 3 * m.face_count());
    for (size_t e = 0; e < t.size(); ++e) {
        CHECK(t.ends[e].x < t.ends[e].y);
        if (e > 0) CHECK((t.ends[e - 1].x < t.ends[e].x ||
                          (t.ends[e - 1].x == t.ends[e].x && t.ends[e - 1].y < t.ends[e].y)));
        CHECK(t.face_count(e) == 2);
        // Its half-edges join its two vertices, in increasing face order.
        for (uint32_t k = t.first[e]; k < t.first[e + 1]; ++k) {
            const uint32_t h = t.halfedges[k];
            const Face& f = m.faces[h / 3];
            const uint32_t a = f[h % 3], b = f[(h % 3 + 1) % 3];
            CHECK(t.ends[e] == glm::uvec2(std::min(a, b), std::max(a, b)));
            if (k > t.first[e]) CHECK(t.halfedges[k - 1] < h);
        }
    }
    // Every half-edge appears exactly once.
    std::vector<uint32_t> sorted = t.halfedges;
    std::sort(sorted.begin(), sorted.end());
    for (size_t h = 0; h < sorted.size(); ++h) CHECK(sorted[h] == h);
}

TEST_CASE("closed icosphere: no boundary, one component, chi = 2", "[topology]") {
    const Mesh m = make_icosphere(1.0f, 3);
    const Topology t = topology_of(m);
    CHECK(t.edges == 3 * m.face_count() / 2);
    CHECK(t.boundary_edges == 0);
    CHECK(t.boundary_loops == 0);
    CHECK(t.nonmanifold_edges == 0);
    CHECK(t.components == 1);
    CHECK(t.isolated_vertices == 0);
    CHECK(t.euler_characteristic == 2);
}

TEST_CASE("torus: chi = 0", "[topology]") {
    const Topology t = topology_of(make_torus(2.0f, 0.5f, 24, 12));
    CHECK(t.euler_characteristic == 0);
    CHECK(t.boundary_edges == 0);
    CHECK(t.components == 1);
}

TEST_CASE("grid: one boundary loop of 4n edges, chi = 1", "[topology]") {
    const int n = 7;
    const Mesh m = make_grid(2.0f, n);
    const Topology t = topology_of(m);
    CHECK(t.boundary_edges == size_t(4 * n));
    CHECK(t.boundary_loops == 1);
    CHECK(t.nonmanifold_edges == 0);
    CHECK(t.components == 1);
    CHECK(t.euler_characteristic == 1);

    const std::vector<uint8_t> flags = vertex_flags_of(m);
    REQUIRE(flags.size() == m.vertex_count());
    for (size_t v = 0; v < m.vertex_count(); ++v) {
        const glm::vec3 p = m.positions[v];
        const bool on_rim = std::abs(std::abs(p.x) - 1.0f) < 1e-6f || std::abs(std::abs(p.y) - 1.0f) < 1e-6f;
        CHECK(bool(flags[v] & kFlagBoundary) == on_rim);
        CHECK(!(flags[v] & kFlagNonManifold));
    }
}

TEST_CASE("one-ring vertex flags agree with the global edge table", "[topology]") {
    // Two independent computations: compute_vertex_basics looks at each vertex's fan only, the
    // edge table counts the faces of every edge. A vertex is boundary (non-manifold) exactly when
    // it ends an edge used by one face (by three or more).
    Mesh m = make_grid(1.0f, 6);
    m.positions.push_back({0.1f, 0.1f, 0.5f});
    m.faces.push_back({10, 11, uint32_t(m.positions.size() - 1)});  // a fin on an interior edge
    for (const Mesh& mesh : {m, make_torus(1.0f, 0.3f, 20, 8)}) {
        const EdgeTable edges = build_edge_table(mesh);
        std::vector<uint8_t> expected(mesh.vertex_count(), 0);
        for (size_t e = 0; e < edges.size(); ++e) {
            const uint32_t n = edges.face_count(e);
            const uint8_t bit = n == 1 ? kFlagBoundary : n > 2 ? kFlagNonManifold : 0;
            expected[edges.ends[e].x] |= bit;
            expected[edges.ends[e].y] |= bit;
        }
        const std::vector<uint8_t> flags = vertex_flags_of(mesh);
        for (size_t v = 0; v < mesh.vertex_count(); ++v)
            CHECK((flags[v] & (kFlagBoundary | kFlagNonManifold)) == expected[v]);
    }
}

TEST_CASE("two disjoint spheres: two components", "[topology]") {
    const Mesh s = make_icosphere(1.0f, 2);
    const Mesh m = merged(s, s, {3, 0, 0});
    const Topology t = topology_of(m);
    CHECK(t.components == 2);
    CHECK(t.euler_characteristic == 4);
    const Components c = find_components(m);
    REQUIRE(c.count == 2);
    for (size_t v = 0; v < m.vertex_count(); ++v) CHECK(c.label[v] == (v < s.vertex_count() ? 0u : 1u));
}

TEST_CASE("three faces on one edge: one non-manifold edge", "[topology]") {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0}, {0.5f, 0, 1}};
    m.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const Topology t = topology_of(m);
    CHECK(t.edges == 7);
    CHECK(t.nonmanifold_edges == 1);
    CHECK(t.boundary_edges == 6);
    // Each face's two boundary edges form a chain ending on the non-manifold
    // edge (mesh_topology.h): three open chains.
    CHECK(t.boundary_loops == 3);
    CHECK(t.components == 1);
    CHECK(t.euler_characteristic == 5 - 7 + 3);

    const std::vector<uint8_t> flags = vertex_flags_of(m);
    CHECK(flags[0] == (kFlagBoundary | kFlagNonManifold));
    CHECK(flags[1] == (kFlagBoundary | kFlagNonManifold));
    for (int v : {2, 3, 4}) CHECK(flags[v] == kFlagBoundary);
}

TEST_CASE("degenerate faces: repeated index, collinear, coincident", "[topology]") {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0, 0, 0}};
    m.faces = {
        {0, 1, 2},  // fine
        {0, 0, 1},  // repeated index
        {0, 1, 3},  // collinear: zero area
        {0, 4, 1},  // vertices 0 and 4 coincide: zero area
    };
    CHECK(count_degenerate_faces(m) == 3);
    CHECK(!is_degenerate_face(m, m.faces[0]));
    // The repeated-index face is left out of the topology; zero-area faces
    // with distinct indices still count.
    const Topology t = topology_of(m);
    CHECK(t.valid_faces == 3);
    CHECK(t.surface_vertices == 5);
}

TEST_CASE("isolated vertices are counted apart from components", "[topology]") {
    Mesh m = make_icosphere(1.0f, 1);
    m.positions.push_back({5, 0, 0});
    m.positions.push_back({6, 0, 0});
    m.positions.push_back({7, 0, 0});
    const Topology t = topology_of(m);
    CHECK(t.isolated_vertices == 3);
    CHECK(t.components == 1);
    CHECK(t.euler_characteristic == 2);  // isolated vertices are not part of the surface
    const Components c = find_components(m);
    CHECK(c.label.back() == kNoComponent);
}

TEST_CASE("sphere with two separate holes: two loops, chi = 0", "[topology]") {
    const Mesh s = make_icosphere(1.0f, 2);
    // Two faces that share no vertex.
    size_t second = 1;
    while (shares_vertex(s.faces[0], s.faces[second])) ++second;
    const Topology t = topology_of(without_faces(s, {0, second}));
    CHECK(t.boundary_edges == 6);
    CHECK(t.boundary_loops == 2);
    CHECK(t.euler_characteristic == 0);
    CHECK(t.components == 1);
}

TEST_CASE("a hole made by removing a vertex's fan is one loop", "[topology]") {
    const Mesh s = make_icosphere(1.0f, 2);
    std::vector<size_t> fan;
    for (size_t f = 0; f < s.face_count(); ++f)
        if (s.faces[f][0] == 0 || s.faces[f][1] == 0 || s.faces[f][2] == 0) fan.push_back(f);
    const Topology t = topology_of(without_faces(s, fan));
    CHECK(t.boundary_edges == fan.size());
    CHECK(t.boundary_loops == 1);
    CHECK(t.isolated_vertices == 1);
    CHECK(t.euler_characteristic == 1);
}

TEST_CASE("holes touching at one vertex are walked as one figure-eight loop", "[topology]") {
    const Mesh s = make_icosphere(1.0f, 2);
    // Two faces around vertex 0 that share only that vertex.
    std::vector<size_t> fan;
    for (size_t f = 0; f < s.face_count(); ++f)
        if (s.faces[f][0] == 0 || s.faces[f][1] == 0 || s.faces[f][2] == 0) fan.push_back(f);
    REQUIRE(fan.size() >= 5);
    size_t a = fan[0], b = 0;
    for (size_t f : fan) {
        int shared = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) shared += s.faces[a][i] == s.faces[f][j];
        if (shared == 1) b = f;
    }
    REQUIRE(b != 0);
    const Topology t = topology_of(without_faces(s, {a, b}));
    CHECK(t.boundary_edges == 6);
    // The fans between the two holes each join one edge of each hole.
    CHECK(t.boundary_loops == 1);
    CHECK(t.euler_characteristic == 0);
}

TEST_CASE("two triangles sharing one vertex (bowtie)", "[topology]") {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
    m.faces = {{0, 1, 2}, {0, 3, 4}};
    const Topology t = topology_of(m);
    CHECK(t.components == 1);
    CHECK(t.boundary_edges == 6);
    CHECK(t.boundary_loops == 2);
    CHECK(t.euler_characteristic == 1);
}

TEST_CASE("empty mesh and faces with bad indices do not crash", "[topology]") {
    const MeshStats empty = compute_mesh_stats(Mesh{});
    CHECK(empty.topology.edges == 0);
    CHECK(empty.topology.components == 0);
    CHECK(empty.edge_lengths.max == 0);

    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.faces = {{0, 1, 2}, {0, 1, 7}};
    const MeshStats s = compute_mesh_stats(m);
    CHECK(s.degenerate_faces == 1);
    CHECK(s.topology.edges == 3);
    CHECK(s.topology.boundary_loops == 1);
}

TEST_CASE("bounding box and edge-length statistics of a grid", "[topology]") {
    const int n = 4;
    const float size = 2.0f, h = size / n;
    const MeshStats s = compute_mesh_stats(make_grid(size, n));
    CHECK(s.bounds.min.x == Approx(-1.0f));
    CHECK(s.bounds.max.y == Approx(1.0f));
    CHECK(s.bounds.size().z == 0.0f);
    // 2 n (n + 1) axis edges of length h, n^2 diagonals of length h sqrt 2.
    const double axis = 2.0 * n * (n + 1), diagonal = double(n) * n;
    CHECK(s.topology.edges == size_t(axis + diagonal));
    CHECK(s.edge_lengths.min == Approx(h));
    CHECK(s.edge_lengths.max == Approx(h * std::sqrt(2.0)));
    CHECK(s.edge_lengths.median == Approx(h));
    CHECK(s.edge_lengths.mean == Approx((axis * h + diagonal * h * std::sqrt(2.0)) / (axis + diagonal)));
}

TEST_CASE("edge-length median: middle value, or mean of the middle pair", "[topology]") {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-2, 0, 0}};
    m.faces = {{0, 1, 2}};  // edges 1, 1, sqrt 2
    CHECK(edge_length_stats(m, build_edge_table(m)).median == Approx(1.0));
    m.faces.push_back({0, 2, 3});  // adds 2 and sqrt 5: 1 1 sqrt2 2 sqrt5
    CHECK(edge_length_stats(m, build_edge_table(m)).median == Approx(std::sqrt(2.0)));
    m.faces.push_back({1, 3, 2});  // adds 3: 1 1 sqrt2 2 sqrt5 3
    CHECK(edge_length_stats(m, build_edge_table(m)).median == Approx(0.5 * (std::sqrt(2.0) + 2.0)));
}
