// The shared test meshes load with the counts given in their README, and the
// fast binary paths agree with the generic reader.
#include "test_io_support.h"
#include "test_support.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

using namespace kappa;
using kappa::test::shared_mesh;

namespace {

struct Expected {
    const char* file;
    size_t vertices, faces;
};

// Every face index is in range and the bounding box is a sensible size.
void check_sane(const Mesh& m) {
    uint32_t max_index = 0;
    for (const Face& f : m.faces) max_index = std::max({max_index, f.x, f.y, f.z});
    CHECK(max_index < m.vertex_count());
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    float diagonal = glm::length(hi - lo);
    CHECK(diagonal > 0.01f);
    CHECK(diagonal < 1000.0f);
}

// Rewrites a binary little-endian PLY of float vertices and uchar/int face
// lists as big-endian (every value is 4 bytes except list counts and the
// dragon's int flags, which are also 4 bytes).
std::string to_big_endian(const std::string& file, const Mesh& m, size_t vertex_props, bool face_flags) {
    size_t header_end = file.find("end_header\n") + 11;
    std::string header = file.substr(0, header_end);
    header.replace(header.find("binary_little_endian"), 20, "binary_big_endian");
    std::string out = header;
    const char* p = file.data() + header_end;
    auto swap4 = [&](const char* q) {
        for (int k = 3; k >= 0; --k) out.push_back(q[k]);
    };
    for (size_t v = 0; v < m.vertex_count(); ++v)
        for (size_t k = 0; k < vertex_props; ++k, p += 4) swap4(p);
    while (p < file.data() + file.size()) {
        int n = uint8_t(*p++);
        out.push_back(char(n));
        for (int k = 0; k < n + (face_flags ? 1 : 0); ++k, p += 4) swap4(p);
    }
    return out;
}

}  // namespace

TEST_CASE("shared meshes load with the documented vertex and face counts", "[io][shared]") {
    const Expected expected[] = {{"bunny.ply", 35947, 69451},
                                 {"dragon-50k.ply", 50000, 100000},
                                 {"fandisk.obj", 6475, 12946},
                                 {"spot.obj", 2930, 5856},
                                 {"bunny-1M.ply", 557164, 1111216}};
    for (const Expected& e : expected) {
        SECTION(e.file) {
            Mesh m = load_mesh(shared_mesh(e.file));
            CHECK(m.vertex_count() == e.vertices);
            CHECK(m.face_count() == e.faces);
            check_sane(m);
        }
    }
}

TEST_CASE("ascii bunny.ply: first vertex and face as written in the file", "[io][shared]") {
    Mesh m = load_mesh(shared_mesh("bunny.ply"));
    // First data line: "-0.0378297 0.12794 0.00447467 0.850855 0.5"
    CHECK(m.positions[0].x == -0.0378297f);
    CHECK(m.positions[0].y == 0.12794f);
    CHECK(m.positions[0].z == 0.00447467f);
    std::string text = kappa::test::read_file(shared_mesh("bunny.ply"));
    // First face line follows the 35947 vertex lines.
    size_t pos = text.find("end_header\n") + 11;
    for (int i = 0; i < 35947; ++i) pos = text.find('\n', pos) + 1;
    unsigned n, a, b, c;
    REQUIRE(std::sscanf(text.c_str() + pos, "%u %u %u %u", &n, &a, &b, &c) == 4);
    CHECK(n == 3);
    CHECK(m.faces[0] == Face(a, b, c));
}

TEST_CASE("OBJ loading keeps every vertex in file order", "[io][shared][obj]") {
    std::string text = kappa::test::read_file(shared_mesh("spot.obj"));
    Mesh m = load_mesh(shared_mesh("spot.obj"));
    // The first `v` line of the file is vertex 0.
    size_t pos = text.find("\nv ") + 3;
    if (text.rfind("v ", 0) == 0) pos = 2;
    float x, y, z;
    REQUIRE(std::sscanf(text.c_str() + pos, "%f %f %f", &x, &y, &z) == 3);
    CHECK(m.positions[0] == glm::vec3(x, y, z));
}

TEST_CASE("binary fast paths agree with the generic reader (big-endian copy)", "[io][shared][ply]") {
    SECTION("bunny-1M: float xyz + confidence, uchar/int faces") {
        std::string file = kappa::test::read_file(shared_mesh("bunny-1M.ply"));
        Mesh fast = read_ply(file.data(), file.size(), "bunny-1M.ply");
        std::string be = to_big_endian(file, fast, 4, false);
        Mesh slow = read_ply(be.data(), be.size(), "bunny-1M-be.ply");
        CHECK(slow.positions == fast.positions);
        CHECK(slow.faces == fast.faces);
    }
    SECTION("dragon-50k: normals and int flags on vertices and faces") {
        std::string file = kappa::test::read_file(shared_mesh("dragon-50k.ply"));
        Mesh fast = read_ply(file.data(), file.size(), "dragon-50k.ply");
        std::string be = to_big_endian(file, fast, 7, true);
        Mesh slow = read_ply(be.data(), be.size(), "dragon-50k-be.ply");
        CHECK(slow.positions == fast.positions);
        CHECK(slow.faces == fast.faces);
    }
}
