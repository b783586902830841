// Midpoint subdivision (geometry/mesh/subdivide.h): four faces for one, one
// new vertex per edge at its midpoint, the same surface (area, normals,
// topology), on a closed sphere and on bunny with its holes.
#include <catch2/catch.hpp>

#include "test_support.h"

#include "geometry/io/mesh_io.h"
#include "geometry/mesh/mesh_stats.h"
#include "geometry/mesh/primitives.h"
#include "geometry/mesh/subdivide.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

using namespace kappa;

namespace {

glm::dvec3 area_vector(const Mesh& m, const Face& f) {
    const glm::dvec3 a(m.positions[f[0]]), b(m.positions[f[1]]), c(m.positions[f[2]]);
    return 0.5 * glm::cross(b - a, c - a);
}

void check_subdivision(const Mesh& in) {
    const Mesh out = subdivide_at_midpoints(in);
    const Topology before = compute_mesh_stats(in).topology, after = compute_mesh_stats(out).topology;
    // V' = V + E, F' = 4F, E' = 2E + 3F: the Euler characteristic, the boundary loops and the
    // components stay; boundary edges double.
    CHECK(out.vertex_count() == in.vertex_count() + before.edges);
    CHECK(out.face_count() == 4 * in.face_count());
    CHECK(after.edges == 2 * before.edges + 3 * in.face_count());
    CHECK(after.euler_characteristic == before.euler_characteristic);
    CHECK(after.boundary_loops == before.boundary_loops);
    CHECK(after.boundary_edges == 2 * before.boundary_edges);
    CHECK(after.components == before.components);
    // The input's vertices keep their numbers and places.
    for (size_t v = 0; v < in.vertex_count(); ++v) REQUIRE(out.positions[v] == in.positions[v]);
    // Each face's four children tile it: their area vectors (area times normal, same winding) add
    // up to the parent's, and the middle child (the parent shrunk by half about its centroid) has
    // a quarter of it. Up to the float rounding of the midpoints: under an ulp of the largest
    // coordinate c (1.2e-7 c) each, which moves an area vector by at most that times the longest
    // edge e, for each of the few corners moved: 1e-6 c e covers it.
    for (size_t f = 0; f < in.face_count(); ++f) {
        const Face& p = in.faces[f];
        double c = 0, e = 0;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 a(in.positions[p[k]]), b(in.positions[p[(k + 1) % 3]]);
            c = std::max({c, std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
            e = std::max(e, glm::length(b - a));
        }
        const double tolerance = 1e-6 * c * e;
        glm::dvec3 children(0);
        for (size_t k = 0; k < 4; ++k) children += area_vector(out, out.faces[4 * f + k]);
        const glm::dvec3 parent = area_vector(in, p), middle = area_vector(out, out.faces[4 * f + 3]);
        REQUIRE(glm::length(children - parent) <= tolerance);
        REQUIRE(glm::length(4.0 * middle - parent) <= 4 * tolerance);
    }
    // Every new vertex is the midpoint of the edge of a parent face: the corners of child 0 are
    // (a, ab, ca).
    for (size_t f = 0; f < in.face_count(); ++f) {
        const Face& p = in.faces[f];
        const Face& c0 = out.faces[4 * f];
        REQUIRE(out.positions[c0[1]] == 0.5f * (in.positions[p[0]] + in.positions[p[1]]));
        REQUIRE(out.positions[c0[2]] == 0.5f * (in.positions[p[2]] + in.positions[p[0]]));
    }
}

}  // namespace

TEST_CASE("midpoint subdivision: four faces for one, a vertex per edge, the same surface", "[geometry][subdivide]") {
    SECTION("a closed sphere") { check_subdivision(make_icosphere(1.0f, 2)); }
    SECTION("bunny, with its holes") { check_subdivision(load_mesh(test::shared_mesh("bunny.ply"))); }
}
