// Bad input gives a MeshLoadError with one line "PATH: problem": never a
// crash, a hang, a huge allocation or a silently partial mesh.
#include "test_io_support.h"
#include "test_support.h"

#include <sys/stat.h>
#include <unistd.h>
#include <cmath>
#include <limits>

using namespace kappa;
using kappa::test::Bytes;
using kappa::test::obj_from;
using kappa::test::off_from;
using kappa::test::ply_from;
using kappa::test::stl_from;

namespace {

const std::string kXyz = "property float x\nproperty float y\nproperty float z\n";
const std::string kFaceList = "element face 1\nproperty list uchar int vertex_indices\n";

std::string ascii_ply(const std::string& vertices_and_faces, int nv = 3, int nf = 1) {
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(nv) + "\n" + kXyz + "element face " +
           std::to_string(nf) + "\nproperty list uchar int vertex_indices\nend_header\n" + vertices_and_faces;
}

// Binary little-endian triangle with the given third face index.
std::string binary_ply(int32_t third_index, float x0 = 0.0f) {
    Bytes b;
    b.text("ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + kXyz + kFaceList + "end_header\n");
    b.le(x0).le(0.0f).le(0.0f).le(1.0f).le(0.0f).le(0.0f).le(0.0f).le(1.0f).le(0.0f);
    b.le(uint8_t(3)).le(int32_t(0)).le(int32_t(1)).le(third_index);
    return b.str();
}

}  // namespace

TEST_CASE("load errors: file system problems name the path", "[io][errors]") {
    std::string dir = kappa::test::temp_dir();
    REQUIRE_LOAD_ERROR(load_mesh(dir + "/missing.ply"), dir + "/missing.ply", "no such file");
    REQUIRE_LOAD_ERROR(load_mesh(dir), dir, "directory");
    kappa::test::write_file(dir + "/empty.ply", "");
    REQUIRE_LOAD_ERROR(load_mesh(dir + "/empty.ply"), dir + "/empty.ply", "empty");
    kappa::test::write_file(dir + "/empty.obj", "");
    REQUIRE_LOAD_ERROR(load_mesh(dir + "/empty.obj"), dir + "/empty.obj", "empty");
    REQUIRE_LOAD_ERROR(load_mesh("/dev/null"), "/dev/null", "not a regular file");

    SECTION("unreadable file") {
        std::string path = dir + "/secret.ply";
        kappa::test::write_file(path, ascii_ply("0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
        ::chmod(path.c_str(), 0);
        if (::access(path.c_str(), R_OK) == 0) {
            WARN("running as root: permissions cannot make a file unreadable, skipped");
        } else {
            REQUIRE_LOAD_ERROR(load_mesh(path), path, "cannot open");
        }
    }
}

TEST_CASE("load errors: content that is not a mesh", "[io][errors]") {
    std::string dir = kappa::test::temp_dir();
    kappa::test::write_file(dir + "/notes.txt", "hello, this is not a mesh\n");
    REQUIRE_LOAD_ERROR(load_mesh(dir + "/notes.txt"), dir + "/notes.txt", "not a recognised mesh file");
    kappa::test::write_file(dir + "/image.ply", "\x89PNG\r\n\x1a\n binary junk");
    REQUIRE_LOAD_ERROR(load_mesh(dir + "/image.ply"), dir + "/image.ply", "not a PLY file");
    kappa::test::write_file(dir + "/text.off", "hello world\n");
    REQUIRE_LOAD_ERROR(load_mesh(dir + "/text.off"), dir + "/text.off", "not an OFF file");
    kappa::test::write_file(dir + "/text.stl", "hello world\n");
    REQUIRE_LOAD_ERROR(load_mesh(dir + "/text.stl"), dir + "/text.stl", "not an STL file");
    kappa::test::write_file(dir + "/text.obj", "hello world\nthis has no vertices\n");
    REQUIRE_LOAD_ERROR(load_mesh(dir + "/text.obj"), dir + "/text.obj", "no vertices");
}

TEST_CASE("load errors: a file with nothing in it", "[io][errors]") {
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat ascii 1.0\nelement vertex 0\n" + kXyz + "end_header\n"),
                       "test.ply", "no vertices");
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat ascii 1.0\nend_header\n"), "test.ply", "no vertices");
    REQUIRE_LOAD_ERROR(off_from("OFF\n0 0 0\n"), "test.off", "no vertices");
    REQUIRE_LOAD_ERROR(off_from("# only a comment\n"), "test.off", "only comments");
    REQUIRE_LOAD_ERROR(stl_from("solid empty\nendsolid empty\n"), "test.stl", "no triangles");
    REQUIRE_LOAD_ERROR(stl_from(Bytes().text(std::string(80, ' ')).le(uint32_t(0)).str()), "test.stl",
                       "no triangles");
    REQUIRE_LOAD_ERROR(obj_from("# nothing\n"), "test.obj", "no vertices");
}

TEST_CASE("load errors: face indices out of range", "[io][errors]") {
    const std::string msg = "face 0 refers to vertex 3 but the file has 3 vertices";
    REQUIRE_LOAD_ERROR(ply_from(ascii_ply("0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n")), "test.ply", msg);
    REQUIRE_LOAD_ERROR(ply_from(binary_ply(3)), "test.ply", msg);
    REQUIRE_LOAD_ERROR(ply_from(binary_ply(-1)), "test.ply", "refers to vertex -1");
    REQUIRE_LOAD_ERROR(ply_from(ascii_ply("0 0 0\n1 0 0\n0 1 0\n4 0 1 2 -7\n")), "test.ply", "vertex -7");
    REQUIRE_LOAD_ERROR(off_from("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), "test.off", msg);
    REQUIRE_LOAD_ERROR(obj_from("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"), "test.obj", msg);
    REQUIRE_LOAD_ERROR(obj_from("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n"), "test.obj", "refers to vertex -1");
    REQUIRE_LOAD_ERROR(obj_from("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "test.obj", "line 4");
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat ascii 1.0\nelement vertex 3\n" + kXyz +
                                "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                                "0 0 0\n1 0 0\n0 1 0\n4 0 1 2 5\n"),
                       "test.ply", "triangle strip 0 refers to vertex 5");
}

TEST_CASE("load errors: the bunny with a bad index names the face and the counts", "[io][errors]") {
    std::string text = kappa::test::read_file(kappa::test::shared_mesh("bunny.ply"));
    size_t pos = text.find("end_header\n") + 11;
    for (int i = 0; i < 35947 + 12; ++i) pos = text.find('\n', pos) + 1;  // face 12
    size_t space = text.find(' ', pos);
    text.replace(space + 1, text.find(' ', space + 1) - space - 1, "40000");
    std::string path = kappa::test::temp_dir() + "/bunny.ply";
    kappa::test::write_file(path, text);
    REQUIRE_LOAD_ERROR(load_mesh(path), path,
                       "face 12 refers to vertex 40000 but the file has 35947 vertices");
}

TEST_CASE("load errors: NaN and infinite coordinates", "[io][errors]") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    REQUIRE_LOAD_ERROR(ply_from(binary_ply(2, nan)), "test.ply", "vertex 0 has a non-finite coordinate");
    REQUIRE_LOAD_ERROR(ply_from(binary_ply(2, -inf)), "test.ply", "non-finite");
    REQUIRE_LOAD_ERROR(ply_from(ascii_ply("0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n")), "test.ply",
                       "vertex 1 has a non-finite");
    REQUIRE_LOAD_ERROR(ply_from(ascii_ply("0 0 0\n1 0 0\n0 1 inf\n3 0 1 2\n")), "test.ply", "vertex 2");
    // A double beyond the float range.
    REQUIRE_LOAD_ERROR(
        ply_from("ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
                 "property double z\nend_header\n1e300 0 0\n"),
        "test.ply", "non-finite");
    REQUIRE_LOAD_ERROR(off_from("OFF\n3 1 0\n0 0 0\n1 0 0\n0 NaN 0\n3 0 1 2\n"), "test.off", "vertex 2");
    REQUIRE_LOAD_ERROR(obj_from("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n"), "test.obj",
                       "bad coordinate 'nan'");
    REQUIRE_LOAD_ERROR(obj_from("v 0 0 0\nv 1 0 1e39\nv 0 1 0\nf 1 2 3\n"), "test.obj", "vertex 1");
    REQUIRE_LOAD_ERROR(stl_from("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex inf 0 0\n"
                                "vertex 0 1 0\nendloop\nendfacet\nendsolid\n"),
                       "test.stl", "triangle 0 has a non-finite");
    Bytes stl;
    stl.text(std::string(80, ' ')).le(uint32_t(1)).le(0.f).le(0.f).le(1.f);
    stl.le(0.f).le(0.f).le(0.f).le(1.f).le(nan).le(0.f).le(0.f).le(1.f).le(0.f).le(uint16_t(0));
    REQUIRE_LOAD_ERROR(stl_from(stl.str()), "test.stl", "non-finite");
}

TEST_CASE("load errors: truncated files and wrong counts", "[io][errors]") {
    SECTION("binary PLY cut anywhere in the body") {
        std::string full = kappa::test::read_file(kappa::test::shared_mesh("dragon-50k.ply"));
        size_t body = full.find("end_header\n") + 11;
        for (size_t cut : {body, body + 1, body + 100001, full.size() - 1}) {
            INFO("cut at " << cut);
            std::string part = full.substr(0, cut);
            REQUIRE_LOAD_ERROR(read_ply(part.data(), part.size(), "dragon.ply"), "dragon.ply", "");
        }
    }
    SECTION("binary PLY, generic path (big-endian)") {
        std::string file = "ply\nformat binary_big_endian 1.0\nelement vertex 3\n" + kXyz + kFaceList +
                           "end_header\n" +
                           Bytes()
                               .be(1.0f)
                               .be(2.0f)
                               .be(3.0f)
                               .be(4.0f)
                               .be(5.0f)
                               .be(6.0f)
                               .be(7.0f)
                               .be(8.0f)
                               .be(9.0f)
                               .be(uint8_t(3))
                               .be(0)
                               .be(1)
                               .str();
        REQUIRE_LOAD_ERROR(ply_from(file), "test.ply", "unexpected end of file in element 'face'");
    }
    SECTION("ascii PLY with fewer vertices than declared") {
        REQUIRE_LOAD_ERROR(ply_from(ascii_ply("0 0 0\n1 0 0\n", 3, 0)), "test.ply", "vertex");
        REQUIRE_LOAD_ERROR(ply_from(ascii_ply("0 0 0\n1 0 0\n0 1 0\n3 0 1\n")), "test.ply", "end of file");
    }
    SECTION("ascii PLY with a bad number") {
        REQUIRE_LOAD_ERROR(ply_from(ascii_ply("0 0 0\n1 0 0\n0 one 0\n3 0 1 2\n")), "test.ply",
                           "bad number 'one' on line 12");
    }
    SECTION("PLY header without end_header") {
        REQUIRE_LOAD_ERROR(ply_from("ply\nformat ascii 1.0\nelement vertex 3\n"), "test.ply", "end_header");
    }
    SECTION("OFF with fewer faces than declared") {
        REQUIRE_LOAD_ERROR(off_from("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "test.off", "end of file");
        REQUIRE_LOAD_ERROR(off_from("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n"), "test.off",
                           "line 4 ends too early");
    }
    SECTION("binary STL whose size does not match its triangle count") {
        std::string stl = Bytes().text(std::string(80, ' ')).le(uint32_t(3)).str() + std::string(100, '\0');
        REQUIRE_LOAD_ERROR(stl_from(stl), "test.stl", "declares 3 triangles");
        // Also when the binary header starts with "solid".
        std::string solid =
            Bytes().text("solid" + std::string(75, ' ')).le(uint32_t(3)).str() + std::string(100, '\0');
        REQUIRE_LOAD_ERROR(stl_from(solid), "test.stl",
                           "declares 3 triangles (234 bytes) but the file has 184 bytes");
    }
    SECTION("ascii STL cut inside a facet, and a facet with 4 corners") {
        REQUIRE_LOAD_ERROR(stl_from("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0"),
                           "test.stl", "end of file inside facet 0");
        REQUIRE_LOAD_ERROR(stl_from("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                    "vertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n"),
                           "test.stl", "more than 3 vertices");
    }
}

TEST_CASE("load errors: absurd counts fail fast without allocating", "[io][errors]") {
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat binary_little_endian 1.0\nelement vertex 999999999999999\n" +
                                kXyz + "end_header\n" + std::string(24, '\0')),
                       "test.ply", "header declares 999999999999999 'vertex' elements");
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat ascii 1.0\nelement vertex 3\n" + kXyz +
                                "element face 18446744073709551615\nproperty list uchar int vertex_indices\n"
                                "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                       "test.ply", "'face' elements");
    REQUIRE_LOAD_ERROR(
        ply_from("ply\nformat ascii 1.0\nelement vertex 18446744073709551616\n" + kXyz + "end_header\n"),
        "test.ply", "element count");
    // A list length of 2^31 - 1 in a 50-byte body.
    Bytes b;
    b.text("ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + kXyz +
           "element face 1\nproperty list int int vertex_indices\nend_header\n");
    for (int i = 0; i < 9; ++i) b.le(0.5f);
    b.le(int32_t(0x7fffffff)).le(int32_t(0)).le(int32_t(1)).le(int32_t(2));
    REQUIRE_LOAD_ERROR(ply_from(b.str()), "test.ply", "'face'");
    REQUIRE_LOAD_ERROR(off_from("OFF\n99999999999 99999999999 0\n0 0 0\n"), "test.off", "header declares");
    REQUIRE_LOAD_ERROR(off_from("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n"), "test.off", "claims");
}

TEST_CASE("load errors: malformed PLY headers", "[io][errors]") {
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat ascii 1.0\nproperty float x\nend_header\n"), "test.ply",
                       "before any element");
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n"),
                       "test.ply", "unknown property type");
    REQUIRE_LOAD_ERROR(
        ply_from("ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\nend_header\n"),
        "test.ply", "integer type");
    REQUIRE_LOAD_ERROR(ply_from("ply\nelement vertex 1\n" + kXyz + "end_header\n0 0 0\n"), "test.ply",
                       "no format");
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat binary_middle_endian 1.0\nend_header\n"), "test.ply",
                       "unknown format");
    REQUIRE_LOAD_ERROR(
        ply_from("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                 "end_header\n0 0\n"),
        "test.ply", "no 'z' property");
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat ascii 1.0\nelement vertex 1\n" + kXyz +
                                "element face 1\nproperty list uchar int corners\nend_header\n0 0 0\n0\n"),
                       "test.ply", "no 'vertex_indices'");
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat ascii 1.0\nbogus line\nend_header\n"), "test.ply",
                       "header line 3 'bogus line'");
}
