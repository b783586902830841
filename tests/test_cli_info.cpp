// `kappa info` end to end: the printed counts against facts known
// independently (mesh README, the default model's construction, V - E + F).
#include "test_support.h"
#include "test_upright_shapes.h"

#include "geometry/io/mesh_io.h"
#include "geometry/view/default_view.h"

#include <glm/geometric.hpp>

#include <catch2/catch.hpp>

#include <cstdio>
#include <utility>

#include <map>
#include <algorithm>
#include <sstream>
#include <string>

using kappa::test::base64;
using kappa::test::count_lines;
using kappa::test::run_command;

namespace {

const std::string kExe = KAPPA_EXE;

// "name: value" lines of the output.
std::map<std::string, std::string> fields(const std::string& output) {
    std::map<std::string, std::string> out;
    std::istringstream in(output);
    std::string line;
    while (std::getline(in, line)) {
        const size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        const size_t value = line.find_first_not_of(' ', colon + 1);
        out[line.substr(0, colon)] = value == std::string::npos ? "" : line.substr(value);
    }
    return out;
}

long long integer(const std::map<std::string, std::string>& f, const std::string& name) {
    auto it = f.find(name);
    REQUIRE(it != f.end());
    return std::stoll(it->second);
}

// V - E + F from the printed counts (isolated vertices are not on the surface).
void check_euler(const std::map<std::string, std::string>& f) {
    REQUIRE(integer(f, "degenerate faces") == 0);
    CHECK(integer(f, "euler characteristic") ==
          integer(f, "vertices") - integer(f, "isolated vertices") - integer(f, "edges") + integer(f, "faces"));
}

}  // namespace

TEST_CASE("kappa info on the built-in model", "[cli][info]") {
    const auto r = run_command(kExe + " info");
    REQUIRE(r.exit_code == 0);
    const auto f = fields(r.output);
    // An icosphere subdivided 6 times: 10 * 4^6 + 2 vertices, 20 * 4^6 faces.
    CHECK(integer(f, "vertices") == 40962);
    CHECK(integer(f, "faces") == 81920);
    CHECK(integer(f, "edges") == 122880);
    CHECK(integer(f, "components") == 1);
    CHECK(integer(f, "boundary edges") == 0);
    CHECK(integer(f, "boundary loops") == 0);
    CHECK(integer(f, "non-manifold edges") == 0);
    CHECK(integer(f, "isolated vertices") == 0);
    CHECK(integer(f, "euler characteristic") == 2);
    check_euler(f);
    REQUIRE(f.count("feature size"));
    const double fs = std::stod(f.at("feature size"));
    CHECK(fs > 0.05);  // the model has radius 1: features are a sizeable fraction of it
    CHECK(fs <= 1.0);
    REQUIRE(f.count("bounding box max"));
    double x, y, z;
    std::istringstream(f.at("bounding box max")) >> x >> y >> z;
    CHECK(std::max({x, y, z}) <= 1.0);
    CHECK(std::max({x, y, z}) > 0.5);
}

TEST_CASE("kappa info on the shared meshes", "[cli][info][shared]") {
    SECTION("bunny.ply: open scan") {
        const auto r = run_command(kExe + " info " + kappa::test::shared_mesh("bunny.ply"));
        REQUIRE(r.exit_code == 0);
        const auto f = fields(r.output);
        CHECK(integer(f, "vertices") == 35947);
        CHECK(integer(f, "faces") == 69451);
        CHECK(integer(f, "boundary edges") > 0);
        CHECK(integer(f, "boundary loops") > 0);
        CHECK(3 * integer(f, "boundary loops") <= integer(f, "boundary edges"));
        check_euler(f);
        // Genus 0 with holes: chi = 2 - loops on its one component.
        CHECK(integer(f, "euler characteristic") == 2 * integer(f, "components") - integer(f, "boundary loops"));
    }
    SECTION("spot.obj: closed genus-0 surface") {
        const auto r = run_command(kExe + " info --no-curvature " + kappa::test::shared_mesh("spot.obj"));
        REQUIRE(r.exit_code == 0);
        const auto f = fields(r.output);
        CHECK(integer(f, "vertices") == 2930);
        CHECK(integer(f, "faces") == 5856);
        CHECK(integer(f, "edges") == 3 * 5856 / 2);  // closed: every edge has two faces
        CHECK(integer(f, "boundary edges") == 0);
        CHECK(integer(f, "euler characteristic") == 2);
        check_euler(f);
        CHECK(f.count("feature size") == 0);
    }
}

TEST_CASE("kappa info on a file it cannot read: one line naming it, exit 1", "[cli][info]") {
    const std::string dir = kappa::test::temp_dir();
    SECTION("missing file") {
        const std::string path = dir + "/no-such-mesh.ply";
        const auto r = run_command(kExe + " info " + path);
        CHECK(r.exit_code == 1);
        CHECK(count_lines(r.output) == 1);
        CHECK(r.output.rfind("kappa: " + path, 0) == 0);
    }
    SECTION("not a mesh") {
        const std::string path = dir + "/garbage.ply";
        kappa::test::write_file(path, "this is not a mesh\n");
        const auto r = run_command(kExe + " info " + path);
        CHECK(r.exit_code == 1);
        CHECK(count_lines(r.output) == 1);
        CHECK(r.output.find(path) != std::string::npos);
    }
}

TEST_CASE("kappa info --help lists its argument and options", "[cli][info]") {
    const auto r = run_command(kExe + " info --help");
    CHECK(r.exit_code == 0);
    for (const char* word : {"MESH", "--no-curvature", "--timings", "--threads", "--help"})
        CHECK(r.output.find(word) != std::string::npos);
}

TEST_CASE("kappa info rejects extra arguments", "[cli][info]") {
    const auto r = run_command(kExe + " info a.ply b.ply");
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.output) == 1);
    CHECK(r.output.find("unexpected argument 'b.ply'") != std::string::npos);
}

namespace {

// The three numbers of "eye X,Y,Z up X,Y,Z" after `key`.
glm::vec3 view_vector(const std::string& line, const std::string& key) {
    const size_t at = line.find(key + " ");
    REQUIRE(at != std::string::npos);
    glm::vec3 v;
    char comma1 = 0, comma2 = 0;
    std::istringstream(line.substr(at + key.size() + 1)) >> v.x >> comma1 >> v.y >> comma2 >> v.z;
    CHECK(comma1 == ',');
    CHECK(comma2 == ',');
    return v;
}

// The mesh as a .gltf with an embedded buffer (float positions, uint32 indices).
std::string gltf_of(const kappa::Mesh& m) {
    const std::string pos(reinterpret_cast<const char*>(m.positions.data()), m.positions.size() * 12);
    const std::string idx(reinterpret_cast<const char*>(m.faces.data()), m.faces.size() * 12);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    char bounds[200];
    std::snprintf(bounds, sizeof bounds, R"("min": [%.9g, %.9g, %.9g], "max": [%.9g, %.9g, %.9g])", lo.x, lo.y, lo.z,
                  hi.x, hi.y, hi.z);
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}], )"
           R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}], )"
           R"("buffers": [{"byteLength": )" + std::to_string(pos.size() + idx.size()) +
           R"(, "uri": "data:application/octet-stream;base64,)" + base64(pos + idx) + R"("}], )" +
           R"("bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" + std::to_string(pos.size()) +
           R"(}, {"buffer": 0, "byteOffset": )" + std::to_string(pos.size()) + R"(, "byteLength": )" +
           std::to_string(idx.size()) + R"(}], "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": )" +
           std::to_string(m.positions.size()) + ", " + bounds +
           R"(}, {"bufferView": 1, "componentType": 5125, "type": "SCALAR", "count": )" +
           std::to_string(3 * m.faces.size()) + "}]}";
}

}  // namespace

TEST_CASE("kappa info prints the default view: the shape's up, or the glTF file's", "[cli][info]") {
    using kappa::test::shared_mesh;
    // Spot: y up, its view as the default view code chooses it.
    {
        const auto r = run_command(kExe + " info --no-curvature " + shared_mesh("spot.obj"));
        REQUIRE(r.exit_code == 0);
        const auto f = fields(r.output);
        REQUIRE(f.count("default view"));
        const glm::vec3 eye = view_vector(f.at("default view"), "eye"), up = view_vector(f.at("default view"), "up");
        CHECK(glm::length(up - glm::vec3(0, 1, 0)) < 1e-4f);
        const glm::vec3 expected = kappa::view_direction(kappa::choose_default_view(kappa::load_mesh(shared_mesh("spot.obj"))));
        CHECK(glm::length(eye - expected) < 2e-4f);
    }
    // A bust standing on its base, z up: as an OFF file z up; as glTF (whose
    // convention is +y) y up, seen from above the y axis.
    const kappa::Mesh bust = kappa::test::bust_z_up();
    const std::string off = kappa::test::temp_dir() + "/bust-z-up.off", gltf = kappa::test::temp_dir() + "/bust.gltf";
    kappa::test::write_off(off, bust);
    kappa::test::write_file(gltf, gltf_of(bust));
    for (const auto& [path, true_up] : {std::pair{off, glm::vec3(0, 0, 1)}, std::pair{gltf, glm::vec3(0, 1, 0)}}) {
        const auto r = run_command(kExe + " info --no-curvature " + path);
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        const auto f = fields(r.output);
        REQUIRE(f.count("default view"));
        const glm::vec3 eye = view_vector(f.at("default view"), "eye"), up = view_vector(f.at("default view"), "up");
        CHECK(glm::length(up - true_up) < 1e-4f);
        CHECK(std::fabs(glm::length(eye) - 1) < 1e-3f);
        CHECK(glm::dot(eye, up) > 0.3f);  // from above: elevation 20 or 35 degrees
        CHECK(glm::dot(eye, up) < 0.6f);
    }
}
