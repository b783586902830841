// OBJ through tinyobjloader: vertex order and count kept, corner syntaxes,
// relative indices, polygons fan-triangulated, other statements ignored.
#include "test_io_support.h"

#include <cmath>

using namespace kappa;
using kappa::test::obj_from;

TEST_CASE("OBJ: v/vt/vn corner forms, negative indices, quads as fans", "[io][obj]") {
    Mesh m = obj_from(
        "# comment\nmtllib missing.mtl\no square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nusemtl none\ns 1\n"
        "f 1/1/1 2/2/1 3/3/1 4//1\n"
        "g other\nv 2 0 0\nf -1 2 3\nf 5/1 4/2 1/3\nl 1 2\np 3\n");
    REQUIRE(m.vertex_count() == 5);
    CHECK(m.positions[4] == glm::vec3(2, 0, 0));
    CHECK(m.faces == std::vector<Face>{{0, 1, 2}, {0, 2, 3}, {4, 1, 2}, {4, 3, 0}});
}

TEST_CASE("OBJ: unreferenced vertices are kept, in file order", "[io][obj]") {
    Mesh m = obj_from("v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 2 3 4\n");
    REQUIRE(m.vertex_count() == 5);
    CHECK(m.positions[0] == glm::vec3(9, 9, 9));
    CHECK(m.positions[4] == glm::vec3(5, 5, 5));
    CHECK(m.faces == std::vector<Face>{{1, 2, 3}});
}

TEST_CASE("OBJ: polygons, vertex colours, CR line endings, exact coordinates", "[io][obj]") {
    Mesh m = obj_from("v 0 0 0 1 0 0\rv 1 0 0 0 1 0\rv 2 1 0\rv 1 2 0\rv 0 2 0\rv -1 1 0.1\rf 1 2 3 4 5 6\r");
    REQUIRE(m.vertex_count() == 6);
    CHECK(m.positions[5] == glm::vec3(-1, 1, 0.1f));  // correctly rounded, as from_chars
    REQUIRE(m.face_count() == 4);
    for (uint32_t k = 0; k < 4; ++k) CHECK(m.faces[k] == Face(0, k + 1, k + 2));
}

TEST_CASE("OBJ: a file of vertices only is a point cloud", "[io][obj]") {
    Mesh m = obj_from("v 1 2 3\nv 4 5 6\n");
    CHECK(m.vertex_count() == 2);
    CHECK(m.face_count() == 0);
}

TEST_CASE("OBJ: polygons up to 255 corners, larger ones are a clear error", "[io][obj]") {
    auto polygon_file = [](int n) {
        std::string s;
        for (int i = 0; i < n; ++i)
            s += "v " + std::to_string(std::cos(i * 0.1)) + " " + std::to_string(std::sin(i * 0.1)) + " 0\n";
        s += "f";
        for (int i = 1; i <= n; ++i) s += " " + std::to_string(i);
        return s + "\n";
    };
    Mesh m = obj_from(polygon_file(255));
    CHECK(m.face_count() == 253);
    // tinyobjloader stores corner counts in a byte.
    REQUIRE_LOAD_ERROR(obj_from(polygon_file(256)), "test.obj", "more than 255 corners");
}

TEST_CASE("OBJ: vertex indices beyond 32 bits are errors quoting the index as written", "[io][obj]") {
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    // tinyobjloader reads indices with atoi: each of these wrapped, to an
    // index out of range (99999999999 -> 1215752190) or, worse, to a valid
    // one (4294967298 -> 2; 99999999999999999999 -> -1, the last vertex;
    // -4294967297 -> -1), which loaded a wrong face without a word.
    for (const std::string index : {"99999999999", "4294967298", "99999999999999999999", "2147483648", "-99999999999",
                                    "-4294967297", "-99999999999999999999", "-2147483649"}) {
        INFO("index " << index);
        REQUIRE_LOAD_ERROR(obj_from(triangle + "f 1 2 " + index + "\n"), "test.obj", "index " + index);
        REQUIRE_LOAD_ERROR(obj_from(triangle + "vt 0 0\nf 1/1 " + index + "/1 3/1\n"), "test.obj", "index " + index);
        REQUIRE_LOAD_ERROR(obj_from(triangle + "f 1 2 3\nf 3 2 1 " + index + "\n"), "test.obj", "line 5: face 1");
    }
    REQUIRE_LOAD_ERROR(obj_from(triangle + "f 1 2 99999999999\n"), "test.obj",
                       "line 4: face 0 refers to vertex 99999999998 but the file has 3 vertices "
                       "(index 99999999999 as written)");
    // Within range of int: as before, with the index as written.
    REQUIRE_LOAD_ERROR(obj_from(triangle + "f 1 2 4\n"), "test.obj",
                       "face 0 refers to vertex 3 but the file has 3 vertices (index 4 as written)");
    REQUIRE_LOAD_ERROR(obj_from(triangle + "f +1 2 -4\n"), "test.obj", "refers to vertex -1");
    // Forward references, relative and explicit '+' indices still load.
    CHECK(obj_from("f 1 2 3\n" + triangle).faces == std::vector<Face>{{0, 1, 2}});
    CHECK(obj_from(triangle + "f -3 +2 -1\nv 5 5 5\nf -1 1 -2\n").faces == std::vector<Face>{{0, 1, 2}, {3, 0, 2}});
}
