// Inside-out meshes (geometry/mesh/orientation.h): closed and nearly closed
// meshes with inward normals are found, those with outward normals and open
// sheets are not, and flipping turns every normal round.
#include <catch2/catch.hpp>

#include "test_support.h"

#include "geometry/culling/back_faces.h"
#include "geometry/io/mesh_io.h"
#include "geometry/curvature/vertex_basics.h"
#include "geometry/mesh/orientation.h"
#include "geometry/mesh/primitives.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/curvature/face_geometry.h"

#include <glm/geometric.hpp>

using namespace kappa;

TEST_CASE("inside-out meshes are recognised, outward and open ones are not", "[geometry][orientation]") {
    Mesh torus = make_torus(1.0f, 0.3f, 48, 24), sphere = make_icosphere(1.0f, 3);
    Mesh bunny = load_mesh(test::shared_mesh("bunny.ply"));  // a scan with holes in its base
    for (Mesh* m : {&torus, &sphere, &bunny}) {
        CHECK(!is_inside_out(*m));
        flip_faces(*m);
        CHECK(is_inside_out(*m));
        flip_faces(*m);
        CHECK(!is_inside_out(*m));
    }
    // An open sheet: its signed volume means nothing, either way round.
    Mesh grid = make_grid(2.0f, 20);
    CHECK(!is_inside_out(grid));
    flip_faces(grid);
    CHECK(!is_inside_out(grid));
    // Nothing to judge.
    CHECK(!is_inside_out(Mesh{}));
}

TEST_CASE("flipping faces turns every vertex normal round", "[geometry][orientation]") {
    Mesh sphere = make_icosphere(1.0f, 2);
    auto normals = [](const Mesh& m) { return compute_vertex_basics(build_vertex_faces(m), compute_face_geometry(m)).normals; };
    const std::vector<glm::vec3> before = normals(sphere);
    flip_faces(sphere);
    const std::vector<glm::vec3> after = normals(sphere);
    REQUIRE(before.size() == after.size());
    for (size_t v = 0; v < before.size(); ++v) CHECK(glm::dot(before[v], after[v]) == Approx(-1.0f).margin(1e-5));
}

// Back faces may be culled (geometry/culling/back_faces.h) only on consistently
// wound, manifold, outward surfaces; the holes are the boundary components.
TEST_CASE("flipping faces with the vertex-face rows makes them the turned mesh's", "[geometry][orientation]") {
    Mesh bunny = load_mesh(test::shared_mesh("bunny.ply"));
    // A degenerate face meeting one vertex twice: its two corners there swap places in the row.
    bunny.faces.push_back({5, 5, 9});
    bunny.faces.push_back({7, 8, 7});
    bunny.faces.push_back({3, 6, 6});
    VertexFaces vf = build_vertex_faces(bunny);
    flip_faces(bunny, &vf);
    const VertexFaces rebuilt = build_vertex_faces(bunny);
    CHECK(vf.offsets == rebuilt.offsets);
    CHECK(vf.corners == rebuilt.corners);
}

TEST_CASE("back faces: cullable surfaces and their holes", "[geometry][orientation]") {
    const Mesh torus = make_torus(1.0f, 0.3f, 48, 24);
    const BackFaceVisibility closed = back_face_visibility(torus);
    CHECK(closed.cullable);
    CHECK(closed.holes.empty());
    // The bunny scan: holes in its base, each listed with its boundary vertices.
    const Mesh bunny = load_mesh(test::shared_mesh("bunny.ply"));
    const BackFaceVisibility scan = back_face_visibility(bunny);
    CHECK(scan.cullable);
    CHECK(scan.holes.size() >= 2);
    size_t hole_vertices = 0;
    for (const auto& h : scan.holes) hole_vertices += h.size();
    CHECK(hole_vertices >= 3 * scan.holes.size());
    // A sphere with two faces removed far apart: two holes of three vertices.
    Mesh open = make_icosphere(1.0f, 2);
    open.faces.erase(open.faces.begin() + 200);
    open.faces.erase(open.faces.begin());
    const BackFaceVisibility two = back_face_visibility(open);
    CHECK(two.cullable);
    REQUIRE(two.holes.size() == 2);
    CHECK(two.holes[0].size() == 3);
    CHECK(two.holes[1].size() == 3);
    // Not cullable: inside out, one face wound the other way, an edge of three faces, an open sheet.
    Mesh inward = torus;
    flip_faces(inward);
    CHECK(!back_face_visibility(inward).cullable);
    Mesh one_flipped = torus;
    std::swap(one_flipped.faces[10][1], one_flipped.faces[10][2]);
    CHECK(!back_face_visibility(one_flipped).cullable);
    Mesh fin = torus;
    const Face f0 = fin.faces[0];
    fin.positions.push_back(glm::vec3(5, 5, 5));
    fin.faces.push_back({f0[1], f0[0], uint32_t(fin.positions.size() - 1)});
    CHECK(!back_face_visibility(fin).cullable);
    CHECK(!back_face_visibility(make_grid(2.0f, 10)).cullable);
    CHECK(!back_face_visibility(Mesh{}).cullable);
}

TEST_CASE("back faces from the rows: the same answer, degenerate faces ignored", "[geometry][orientation]") {
    // The rows and a known orientation give what the mesh alone gives.
    Mesh open = make_icosphere(1.0f, 2);
    open.faces.erase(open.faces.begin() + 200);
    open.faces.erase(open.faces.begin());
    const BackFaceVisibility alone = back_face_visibility(open);
    const BackFaceVisibility given = back_face_visibility(open, build_vertex_faces(open), true);
    CHECK(given.cullable == alone.cullable);
    CHECK(given.holes == alone.holes);
    // Holes in order of their smallest vertex, each with its vertices in increasing order.
    REQUIRE(given.holes.size() == 2);
    const Mesh whole = make_icosphere(1.0f, 2);
    const Face a = whole.faces[0], b = whole.faces[200];
    const uint32_t smallest = std::min({a[0], a[1], a[2], b[0], b[1], b[2]});
    CHECK(given.holes[0][0] == open.positions[smallest]);
    // Told the normals point inwards: not cullable, whatever the edges.
    CHECK(!back_face_visibility(open, build_vertex_faces(open), false).cullable);
    // A face that repeats a vertex has no edges (edge_table.h): it neither opens nor breaks an edge.
    Mesh torus = make_torus(1.0f, 0.3f, 48, 24);
    const Face f0 = torus.faces[0];
    torus.faces.push_back({f0[0], f0[0], f0[1]});
    torus.faces.push_back({f0[1], f0[0], f0[1]});
    const BackFaceVisibility with_degenerate = back_face_visibility(torus);
    CHECK(with_degenerate.cullable);
    CHECK(with_degenerate.holes.empty());
    // A vertex of huge degree (a fan of 100 faces closing a cone) is checked like any other.
    Mesh cone;
    cone.positions.push_back({0, 0, 1});
    cone.positions.push_back({0, 0, -0.1f});
    for (int i = 0; i < 100; ++i) {
        const float a = 2 * 3.14159265f * i / 100;
        cone.positions.push_back({std::cos(a), std::sin(a), 0});
    }
    for (uint32_t i = 0; i < 100; ++i) {
        const uint32_t a = 2 + i, b = 2 + (i + 1) % 100;
        cone.faces.push_back({0, a, b});
        cone.faces.push_back({1, b, a});
    }
    CHECK(back_face_visibility(cone).cullable);
    cone.faces.push_back({0, 2, 3});  // the edge 0-2 now used twice from 0 to 2
    CHECK(!back_face_visibility(cone).cullable);
    // Rows of another mesh are a caller's mistake, said at once.
    CHECK_THROWS_AS(back_face_visibility(open, build_vertex_faces(torus), true), std::invalid_argument);
}
