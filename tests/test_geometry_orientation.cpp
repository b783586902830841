// Inside-out meshes (geometry/orientation.h): closed and nearly closed
// meshes with inward normals are found, those with outward normals and open
// sheets are not, and flipping turns every normal round.
#include <catch2/catch.hpp>

#include "test_support.h"

#include "geometry/io/mesh_io.h"
#include "geometry/normals.h"
#include "geometry/orientation.h"
#include "geometry/primitives.h"
#include "geometry/vertex_faces.h"
#include "geometry/face_geometry.h"

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
    auto normals = [](const Mesh& m) { return compute_vertex_normals(build_vertex_faces(m), compute_face_geometry(m)); };
    const std::vector<glm::vec3> before = normals(sphere);
    flip_faces(sphere);
    const std::vector<glm::vec3> after = normals(sphere);
    REQUIRE(before.size() == after.size());
    for (size_t v = 0; v < before.size(); ++v) CHECK(glm::dot(before[v], after[v]) == Approx(-1.0f).margin(1e-5));
}
