// `kappa info` end to end: the printed counts against facts known
// independently (mesh README, the default model's construction, V - E + F).
#include "test_support.h"

#include <catch2/catch.hpp>

#include <map>
#include <algorithm>
#include <sstream>
#include <string>

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
