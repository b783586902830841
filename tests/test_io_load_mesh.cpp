// load_mesh: format by extension (any case), by content when the extension
// is missing or unknown.
#include "test_io_support.h"
#include "test_support.h"

using namespace kappa;

namespace {

struct Sample {
    const char* format;
    std::string text;
};

// The same triangle in each text format.
const Sample kSamples[] = {
    {"ply",
     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
     "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
    {"obj", "# a triangle\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
    {"off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
    {"stl",
     "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
     "endsolid t\n"},
};

void check_triangle(const Mesh& m) {
    REQUIRE(m.vertex_count() == 3);
    CHECK(m.positions[1] == glm::vec3(1, 0, 0));
    CHECK(m.faces == std::vector<Face>{{0, 1, 2}});
}

}  // namespace

TEST_CASE("load_mesh: extensions in any case, and content sniffing", "[io][load]") {
    std::string dir = kappa::test::temp_dir();
    for (const Sample& s : kSamples) {
        INFO(s.format);
        std::string upper = s.format;
        for (char& c : upper) c = char(std::toupper(c));
        for (const std::string& name :
             {"mesh." + std::string(s.format), "MESH." + upper, std::string(s.format) + "-no-extension",
              std::string(s.format) + ".data"}) {
            INFO(name);
            kappa::test::write_file(dir + "/" + name, s.text);
            check_triangle(load_mesh(dir + "/" + name));
        }
    }
}

TEST_CASE("format_from_extension and format_from_content", "[io][load]") {
    CHECK(format_from_extension("a/b.c/mesh.Ply") == MeshFormat::Ply);
    CHECK(format_from_extension("x.OFF") == MeshFormat::Off);
    CHECK(format_from_extension("dir.obj/mesh") == MeshFormat::Unknown);
    CHECK(format_from_extension("mesh.ply.gz") == MeshFormat::Unknown);
    const MeshFormat expected[] = {MeshFormat::Ply, MeshFormat::Obj, MeshFormat::Off, MeshFormat::Stl};
    for (size_t i = 0; i < std::size(kSamples); ++i)
        CHECK(format_from_content(kSamples[i].text.data(), kSamples[i].text.size()) == expected[i]);
    CHECK(format_from_content("hello", 5) == MeshFormat::Unknown);
}
