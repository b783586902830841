// Inputs found by the fuzz targets (fuzz/README.md), reduced by hand. Each
// once triggered undefined behaviour or a crash; every reader must now load
// them or throw MeshLoadError. Most of them only fail visibly in a
// sanitizer build (fuzz/ or -fsanitize=address,undefined), where these tests
// are most useful.
#include "test_io_support.h"

#include "geometry/io/gltf_io.h"

using namespace kappa;
using kappa::test::obj_from;
using kappa::test::ply_from;

namespace {

// Runs a reader: fine if it returns a mesh or throws MeshLoadError.
template <typename Read>
void survives(Read&& read) {
    try {
        Mesh m = read();
        CHECK(m.vertex_count() > 0);
    } catch (const MeshLoadError& e) {
        CHECK(std::string(e.what()).find('\n') == std::string::npos);
    }
}

}  // namespace

TEST_CASE("fuzz regression: binary PLY with zero vertices (memcpy from a null vector)", "[io][fuzz]") {
    // The fast vertex path called memcpy(nullptr, p, 0): undefined behaviour.
    REQUIRE_LOAD_ERROR(ply_from("ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\n"
                                "property float y\nproperty float z\nelement tristrips 1\n"
                                "property list int int vertex_indices\nend_header\n" +
                                std::string(4, '\0')),
                       "test.ply", "no vertices");
}

TEST_CASE("fuzz regression: OBJ 'vw' statement with an infinite joint id", "[io][fuzz]") {
    // tinyobjloader's skin-weight extension converted inf to int (undefined
    // behaviour); statements other than v and f no longer reach it.
    const std::string input =
        "# seed\nm qlib a.mtl\no thing\nv 010 0\n3\nf 5/1 4/2 1/3\nl 1 2\np 3\n"
        "vw 0 0 ///1 2/2/1 3/3/1 1e39\x0b" +
        std::string(3, '\0') + "0*5\n";
    survives([&] { return obj_from(input); });
    Mesh m = obj_from("v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 0 1e39 0.5\nf 1 2 3\n");
    CHECK(m.face_count() == 1);
}

TEST_CASE("fuzz regression: .glb whose one buffer has byteLength 0 beside a BIN chunk", "[io][fuzz]") {
    // tinygltf threw std::out_of_range (vector::at) from inside its loader;
    // kappa printed it without the file's name (the fuzz target aborted).
    const std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":0}]})";  // 56 bytes
    auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    REQUIRE(json.size() % 4 == 0);
    const std::string bin(8, '\0');
    const std::string glb = "glTF" + u32(2) + u32(uint32_t(12 + 8 + json.size() + 8 + bin.size())) +
                            u32(uint32_t(json.size())) + "JSON" + json + u32(uint32_t(bin.size())) + std::string("BIN\0", 4) +
                            bin;
    REQUIRE_LOAD_ERROR(read_gltf(glb.data(), glb.size(), "test.glb"), "test.glb", "glTF: ");
}
