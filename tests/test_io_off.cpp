// OFF variants: comments, COFF/NOFF/STOFF extra values, face colours,
// polygons, counts on the keyword line, nOFF.
#include "test_io_support.h"

using namespace kappa;
using kappa::test::off_from;

namespace {
const std::vector<Face> kPyramidFaces = {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
}

TEST_CASE("OFF: plain file with a quad and triangles", "[io][off]") {
    Mesh m = off_from(
        "OFF\n5 5 8\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
        "4 0 1 2 3\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n");
    REQUIRE(m.vertex_count() == 5);
    CHECK(m.positions[4] == glm::vec3(0.5f, 0.5f, 1));
    CHECK(m.faces == kPyramidFaces);
}

TEST_CASE("OFF: comments anywhere, blank lines, CRLF, counts on the keyword line", "[io][off]") {
    Mesh m = off_from(
        "# made by hand\r\nOFF 5 5 0 # counts here\r\n\r\n# vertices\r\n0 0 0\r\n1 0 0 # a comment\r\n"
        "1 1 0\r\n0 1 0\r\n0.5 0.5 1\r\n# faces\r\n4 0 1 2 3\r\n3 0 1 4\r\n3 1 2 4\r\n3 2 3 4\r\n3 3 0 4");
    CHECK(m.vertex_count() == 5);
    CHECK(m.faces == kPyramidFaces);
}

TEST_CASE("OFF: COFF, NOFF, CNOFF, STOFF extra per-vertex values and face colours", "[io][off]") {
    struct Variant {
        const char* keyword;
        const char* extra;  // appended to each vertex line
    };
    const Variant variants[] = {{"COFF", " 255 0 0 255"},
                                {"COFF", " 0.5 0.5 0.5"},
                                {"NOFF", " 0 0 1"},
                                {"CNOFF", " 0 0 1 1 0 0 1"},
                                {"STCNOFF", " 0 0 1 0.2 0.3 0.4 1 0.5 0.5"},
                                {"STOFF", " 0.5 0.25"}};
    for (const Variant& v : variants) {
        INFO(v.keyword << v.extra);
        std::string text = std::string(v.keyword) + "\n5 5 8\n";
        const char* coords[] = {"0 0 0", "1 0 0", "1 1 0", "0 1 0", "0.5 0.5 1"};
        for (const char* c : coords) text += std::string(c) + v.extra + "\n";
        // face colours: none, RGB, RGBA, a colour-map index
        text += "4 0 1 2 3 1 0 0\n3 0 1 4 0.1 0.2 0.3 0.4\n3 1 2 4 7\n3 2 3 4\n3 3 0 4 255 255 255\n";
        Mesh m = off_from(text);
        CHECK(m.vertex_count() == 5);
        CHECK(m.positions[4] == glm::vec3(0.5f, 0.5f, 1));
        CHECK(m.faces == kPyramidFaces);
    }
}

TEST_CASE("OFF: nOFF with dimension 3, polygons, vertices without faces", "[io][off]") {
    Mesh m = off_from("nOFF\n3\n6 1 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 2 0\n-1 1 0\n6 0 1 2 3 4 5\n");
    CHECK(m.vertex_count() == 6);
    REQUIRE(m.face_count() == 4);
    CHECK(m.faces[3] == Face(0, 4, 5));

    Mesh points = off_from("OFF\n2 0 0\n1 2 3\n4 5 6\n");
    CHECK(points.vertex_count() == 2);
    CHECK(points.face_count() == 0);
}

TEST_CASE("OFF: unsupported variants are clear errors", "[io][off]") {
    REQUIRE_LOAD_ERROR(off_from("4OFF\n1 0 0\n1 2 3 4\n"), "test.off", "3-D");
    REQUIRE_LOAD_ERROR(off_from("nOFF\n2\n1 0 0\n1 2\n"), "test.off", "3-D");
    REQUIRE_LOAD_ERROR(off_from("OFF BINARY\n"), "test.off", "binary OFF");
}

TEST_CASE("OFF: counts and indices beyond their integer types are errors quoting them as written", "[io][off]") {
    // 4nOFF adds a homogeneous coordinate to the dimension written: the
    // largest uint64 plus one wrapped to 0 ("this one has dimension 0").
    REQUIRE_LOAD_ERROR(off_from("4nOFF\n18446744073709551615\n1 0 0\n1 2 3 4\n"), "test.off",
                       "dimension 18446744073709551615 + 1");
    REQUIRE_LOAD_ERROR(off_from("nOFF\n18446744073709551616\n1 0 0\n1 2 3\n"), "test.off",
                       "'18446744073709551616'");
    // Counts: beyond uint64, and beyond the 32-bit vertex numbers of a mesh.
    REQUIRE_LOAD_ERROR(off_from("OFF\n99999999999999999999 1 0\n0 0 0\n"), "test.off", "'99999999999999999999'");
    REQUIRE_LOAD_ERROR(off_from("OFF\n3 99999999999999999999 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "test.off",
                       "'99999999999999999999'");
    REQUIRE_LOAD_ERROR(off_from("OFF\n4294967296 1 0\n0 0 0\n"), "test.off", "4294967296");
    // Face indices, and the number of vertices of a face.
    const std::string triangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
    REQUIRE_LOAD_ERROR(off_from(triangle + "3 0 1 99999999999\n"), "test.off",
                       "face 0 refers to vertex 99999999999 but the file has 3 vertices");
    REQUIRE_LOAD_ERROR(off_from(triangle + "3 0 1 4294967296\n"), "test.off", "refers to vertex 4294967296");
    REQUIRE_LOAD_ERROR(off_from(triangle + "3 0 1 -4294967297\n"), "test.off", "refers to vertex -4294967297");
    REQUIRE_LOAD_ERROR(off_from(triangle + "3 0 1 99999999999999999999\n"), "test.off", "'99999999999999999999'");
    REQUIRE_LOAD_ERROR(off_from(triangle + "18446744073709551615 0 1 2\n"), "test.off", "18446744073709551615");
    REQUIRE_LOAD_ERROR(off_from(triangle + "18446744073709551616 0 1 2\n"), "test.off", "'18446744073709551616'");
    REQUIRE_LOAD_ERROR(off_from(triangle + "-3 0 1 2\n"), "test.off", "'-3'");
}
