// Sharp edges (geometry/mesh/creases.h): which edges are creases, the automatic
// default that finds them on CAD parts and not on smooth or scanned meshes,
// and the split that gives each side its own vertices.
#include "test_support.h"

#include "geometry/mesh/creases.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/primitives.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "test_shapes.h"

#include <catch2/catch.hpp>

#include <set>

using namespace kappa;

namespace {


// A closed cylinder around z: n segments, one ring of quads (two triangles
// each), flat caps as fans around a centre vertex.
Mesh cylinder(int n) {
    Mesh m;
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < n; ++i) {
            const float a = 2.0f * float(M_PI) * float(i) / float(n);
            m.positions.push_back({std::cos(a), std::sin(a), float(k)});
        }
    const uint32_t bottom = uint32_t(m.positions.size()), top = bottom + 1;
    m.positions.push_back({0, 0, 0});
    m.positions.push_back({0, 0, 1});
    for (int i = 0; i < n; ++i) {
        const uint32_t a = uint32_t(i), b = uint32_t((i + 1) % n), c = a + uint32_t(n), d = b + uint32_t(n);
        m.faces.push_back({a, b, d});
        m.faces.push_back({a, d, c});
        m.faces.push_back({bottom, b, a});
        m.faces.push_back({top, c, d});
    }
    return m;
}

}  // namespace

TEST_CASE("Creases: the edges whose faces turn by more than the angle", "[creases]") {
    const Mesh cube = test::unit_cube();
    CHECK(find_creases(cube, 40).size() == 12);  // the diagonals of the square faces are flat
    CHECK(find_creases(cube, 95).empty());
    CHECK(find_creases(cube, 0).empty());        // 0: off
    const Mesh cyl = cylinder(32);
    CHECK(find_creases(cyl, 40).size() == 64);   // the two rims; the side turns by 11.25 degrees per edge
    CHECK(find_creases(make_icosphere(1, 3), 40).empty());
}

TEST_CASE("Creases: the automatic default finds CAD edges and leaves smooth and scanned meshes alone", "[creases]") {
    CHECK(auto_crease_angle(test::unit_cube()) == kAutoCreaseAngle);
    CHECK(auto_crease_angle(cylinder(32)) == kAutoCreaseAngle);
    CHECK(auto_crease_angle(cylinder(12)) == kAutoCreaseAngle);
    const Mesh fandisk = load_mesh(test::shared_mesh("fandisk.obj"));
    REQUIRE(auto_crease_angle(fandisk) == kAutoCreaseAngle);
    const size_t fandisk_creases = find_creases(fandisk, kAutoCreaseAngle).size();
    CHECK(fandisk_creases > 600);  // measured 710: its sharp edges, chains of a few hundred edges
    for (const char* name : {"bunny.ply", "bunny-1M.ply", "dragon-50k.ply", "spot.obj"}) {
        INFO(name);
        CHECK(auto_crease_angle(load_mesh(test::shared_mesh(name))) == 0.0f);
    }
    CHECK(auto_crease_angle(make_icosphere(1, 4)) == 0.0f);
}

TEST_CASE("Creases: a split within the room a reader and the rows leave moves no array", "[creases]") {
    // Readers reserve positions_room for the positions and build_vertex_faces as much for the row starts:
    // the copies a split appends fit, and neither array of a big mesh is copied whole.
    Mesh cube = test::unit_cube();
    cube.positions.reserve(positions_room(cube.vertex_count()));
    const std::vector<glm::uvec2> creases = find_creases(cube, 40);
    VertexFaces rows = build_vertex_faces(cube);
    const glm::vec3* positions = cube.positions.data();
    const uint32_t* offsets = rows.offsets.data();
    const uint32_t* corners = rows.corners.data();
    const SplitMesh s = split_at_creases(std::move(cube), creases, &rows);
    REQUIRE(s.copied_from.size() == 16);
    CHECK(s.mesh.positions.data() == positions);
    CHECK(rows.offsets.data() == offsets);
    CHECK(rows.corners.data() == corners);
    const VertexFaces rebuilt = build_vertex_faces(s.mesh);  // the rows are the split mesh's
    CHECK(rows.offsets == rebuilt.offsets);
    CHECK(rows.corners == rebuilt.corners);
}

TEST_CASE("Creases: the split gives each side of a crease its own vertices", "[creases]") {
    const Mesh cube = test::unit_cube();
    const SplitMesh s = split_at_creases(cube, find_creases(cube, 40));
    // Every cube corner meets three faces of different planes: three copies each.
    CHECK(s.mesh.vertex_count() == 24);
    CHECK(s.mesh.face_count() == 12);
    REQUIRE(s.copied_from.size() == 16);
    for (size_t v = 0; v < 24; ++v) CHECK(s.mesh.positions[v] == cube.positions[s.original(v)]);
    for (size_t v = 0; v < 8; ++v) CHECK(s.original(v) == v);  // the first side keeps the number
    // No vertex is shared by two faces of different planes.
    for (size_t v = 0; v < 24; ++v) {
        std::set<std::tuple<float, float, float>> planes;
        for (const Face& f : s.mesh.faces)
            if (f[0] == v || f[1] == v || f[2] == v) {
                const glm::vec3 n = glm::normalize(glm::cross(s.mesh.positions[f[1]] - s.mesh.positions[f[0]],
                                                              s.mesh.positions[f[2]] - s.mesh.positions[f[0]]));
                planes.insert({std::round(n.x), std::round(n.y), std::round(n.z)});
            }
        CHECK(planes.size() == 1);
    }
    CHECK(s.creases.size() == 12);
    REQUIRE(s.crease_faces.size() == 12);
    // Without creases nothing changes.
    const SplitMesh none = split_at_creases(cube, {});
    CHECK(none.mesh.faces == cube.faces);
    CHECK(none.mesh.vertex_count() == 8);
    CHECK(none.copied_from.empty());
}
