// Topology of the shared real meshes, checked against a slow reference count
// written independently here (std::map of vertex pairs, breadth-first search).
#include <catch2/catch.hpp>

#include "test_support.h"

#include "geometry/io/mesh_io.h"
#include "geometry/mesh/mesh_stats.h"
#include "geometry/mesh/mesh_topology.h"

#include <map>
#include <queue>
#include <utility>

using namespace kappa;

namespace {

struct Reference {
    size_t edges = 0, boundary = 0, nonmanifold = 0, components = 0, isolated = 0;
    long long chi = 0;
};

Reference reference_topology(const Mesh& m) {
    Reference r;
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    std::vector<std::vector<uint32_t>> neighbours(m.vertex_count());
    std::vector<bool> used(m.vertex_count(), false);
    for (const Face& f : m.faces)
        for (int i = 0; i < 3; ++i) {
            const uint32_t a = f[i], b = f[(i + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
            neighbours[a].push_back(b);
            neighbours[b].push_back(a);
            used[a] = true;
        }
    r.edges = uses.size();
    for (const auto& [edge, n] : uses) {
        r.boundary += n == 1;
        r.nonmanifold += n > 2;
    }
    std::vector<bool> seen(m.vertex_count(), false);
    size_t used_count = 0;
    for (uint32_t v = 0; v < m.vertex_count(); ++v) {
        if (!used[v]) {
            ++r.isolated;
            continue;
        }
        ++used_count;
        if (seen[v]) continue;
        ++r.components;
        std::queue<uint32_t> todo;
        todo.push(v);
        seen[v] = true;
        while (!todo.empty()) {
            const uint32_t x = todo.front();
            todo.pop();
            for (uint32_t y : neighbours[x])
                if (!seen[y]) seen[y] = true, todo.push(y);
        }
    }
    r.chi = (long long)used_count - (long long)r.edges + (long long)m.face_count();
    return r;
}

void check_against_reference(const Mesh& m) {
    const MeshStats s = compute_mesh_stats(m);
    const Reference r = reference_topology(m);
    CHECK(s.degenerate_faces == 0);  // so every face is valid for the reference too
    CHECK(s.topology.edges == r.edges);
    CHECK(s.topology.boundary_edges == r.boundary);
    CHECK(s.topology.nonmanifold_edges == r.nonmanifold);
    CHECK(s.topology.components == r.components);
    CHECK(s.topology.isolated_vertices == r.isolated);
    CHECK(s.topology.euler_characteristic == r.chi);
    // A loop has at least three edges; with boundary edges there is a loop.
    CHECK(3 * s.topology.boundary_loops <= s.topology.boundary_edges);
    CHECK((s.topology.boundary_loops > 0) == (s.topology.boundary_edges > 0));
    // For orientable manifold pieces chi + loops = 2 (components - genus): even.
    if (s.topology.nonmanifold_edges == 0)
        CHECK((s.topology.euler_characteristic + (long long)s.topology.boundary_loops) % 2 == 0);
}

}  // namespace

TEST_CASE("bunny.ply: a scan with holes", "[topology][shared]") {
    const Mesh m = load_mesh(test::shared_mesh("bunny.ply"));
    REQUIRE(m.vertex_count() == 35947);
    REQUIRE(m.face_count() == 69451);
    check_against_reference(m);
    const Topology t = compute_mesh_stats(m).topology;
    CHECK(t.boundary_edges > 0);
    CHECK(t.boundary_loops >= 2);
    CHECK(t.nonmanifold_edges == 0);
    // The bunny is a sphere with holes: chi = 2 - 2 genus - holes with genus 0
    // (the reference above confirms the component count).
    CHECK(t.components == 1);
    CHECK(t.euler_characteristic == 2 - (long long)t.boundary_loops);
}

TEST_CASE("spot.obj and fandisk.obj: closed surfaces", "[topology][shared]") {
    for (const char* name : {"spot.obj", "fandisk.obj"}) {
        INFO(name);
        const Mesh m = load_mesh(test::shared_mesh(name));
        check_against_reference(m);
    }
}

TEST_CASE("dragon-50k.ply agrees with the reference", "[topology][shared]") {
    check_against_reference(load_mesh(test::shared_mesh("dragon-50k.ply")));
}
