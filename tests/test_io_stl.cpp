// STL: ASCII and binary, detection by size, exact welding of shared corners.
#include "test_io_support.h"
#include "test_support.h"

using namespace kappa;
using kappa::test::Bytes;
using kappa::test::stl_from;

namespace {

// A unit square as two triangles (4 distinct corners, 6 corner records).
const glm::vec3 kTriangles[2][3] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};

std::string binary_stl(const std::string& header80) {
    Bytes b;
    std::string h = header80;
    h.resize(80, ' ');
    b.text(h).le(uint32_t(2));
    for (const auto& t : kTriangles) {
        b.le(0.0f).le(0.0f).le(1.0f);  // normal
        for (const glm::vec3& p : t) b.le(p.x).le(p.y).le(p.z);
        b.le(uint16_t(0));
    }
    return b.str();
}

void check_square(const Mesh& m) {
    REQUIRE(m.vertex_count() == 4);
    // First-occurrence order: (0,0,0) (1,0,0) (1,1,0) (0,1,0).
    CHECK(m.positions[0] == glm::vec3(0, 0, 0));
    CHECK(m.positions[1] == glm::vec3(1, 0, 0));
    CHECK(m.positions[2] == glm::vec3(1, 1, 0));
    CHECK(m.positions[3] == glm::vec3(0, 1, 0));
    CHECK(m.faces == std::vector<Face>{{0, 1, 2}, {0, 2, 3}});
}

}  // namespace

TEST_CASE("STL: binary file, welded in first-occurrence order", "[io][stl]") {
    check_square(stl_from(binary_stl("binary STL written by a test")));
}

TEST_CASE("STL: binary file whose header starts with 'solid' is still binary", "[io][stl]") {
    check_square(stl_from(binary_stl("solid square exported as binary")));
}

TEST_CASE("STL: ascii file, any keyword case, several solids", "[io][stl]") {
    std::string text =
        "solid square\n"
        "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n      vertex 1 1 0\n"
        "    endloop\n  endfacet\nendsolid square\n"
        "SOLID second part\n FACET NORMAL 0 0 1\n OUTER LOOP\n VERTEX 0 0 0\n VERTEX 1 1 0\n VERTEX 0 1 0\n"
        " ENDLOOP\n ENDFACET\nENDSOLID\n";
    check_square(stl_from(text));
}

TEST_CASE("STL: welding is exact (-0 equals +0, nearby points stay apart)", "[io][stl]") {
    std::string text =
        "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 "
        "0\nendloop\nendfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex -0 0 -0\nvertex 1.0000001 0 0\nvertex 0 1 "
        "0\nendloop\nendfacet\n"
        "endsolid s\n";
    Mesh m = stl_from(text);
    REQUIRE(m.vertex_count() == 4);
    CHECK(m.faces == std::vector<Face>{{0, 1, 2}, {0, 3, 2}});
}

TEST_CASE("STL: load_mesh uses the size rule for .stl files and sniffing without extension", "[io][stl]") {
    std::string dir = kappa::test::temp_dir();
    kappa::test::write_file(dir + "/a.STL", binary_stl("solid"));
    kappa::test::write_file(dir + "/noextension", binary_stl("anything"));
    check_square(load_mesh(dir + "/a.STL"));
    check_square(load_mesh(dir + "/noextension"));
}

TEST_CASE("STL: a binary triangle count whose byte size overflows 32 bits is an error quoting it", "[io][stl]") {
    // One triangle (134 bytes) declaring 2^31 + 1 triangles: 84 + 50 n is
    // 134 modulo 2^32, so a size computed in 32 bits would take the file
    // for binary STL of that many triangles.
    Bytes b;
    b.text(std::string(80, ' ')).le(uint32_t(0x80000001));
    for (int k = 0; k < 12; ++k) b.le(float(k % 3 == 0));
    b.le(uint16_t(0));
    REQUIRE(b.str().size() == 134);
    REQUIRE_LOAD_ERROR(stl_from(b.str()), "test.stl",
                       "declares 2147483649 triangles (107374182534 bytes) but the file has 134 bytes");
    // The largest count.
    std::string largest = Bytes().text(std::string(80, ' ')).le(uint32_t(0xffffffff)).str() + std::string(50, '\0');
    REQUIRE_LOAD_ERROR(stl_from(largest), "test.stl", "declares 4294967295 triangles (214748364834 bytes)");
}
