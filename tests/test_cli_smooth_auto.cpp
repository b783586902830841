// `--smooth auto` on the command line: the summary reports the noise and the
// widths, the PLY header records them, explicit widths are kept, the CSV
// stays exactly the columns of conventions.md.
#include "test_support.h"

#include "geometry/mesh/primitives.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <regex>
#include <string>

using namespace kappa;
using kappa::test::read_file;
using kappa::test::run_command;

namespace {

const std::string kExe = KAPPA_EXE;

// A torus with normal noise of 2% of its edge length (about 0.031 / 0.025), as OFF.
std::string noisy_torus_file(const std::string& dir) {
    Mesh m = make_torus(1.0f, 0.4f, 120, 60);
    add_normal_noise(m, 0.02f * 0.045f, 21);
    const std::string path = dir + "/torus.off";
    std::ofstream f(path);
    f.precision(9);
    f << "OFF\n" << m.positions.size() << " " << m.faces.size() << " 0\n";
    for (const auto& p : m.positions) f << p.x << " " << p.y << " " << p.z << "\n";
    for (const auto& t : m.faces) f << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    return path;
}

// The number after `key` in text, or -1.
double number_after(const std::string& text, const std::string& key) {
    const auto at = text.find(key);
    if (at == std::string::npos) return -1;
    return std::stod(text.substr(at + key.size()));
}

}  // namespace

TEST_CASE("kappa curvature --smooth auto prints the noise and the widths and records them in the PLY",
          "[cli][curvature][smooth-auto]") {
    const std::string dir = test::temp_dir();
    const std::string mesh = noisy_torus_file(dir);
    const auto r = run_command(kExe + " curvature " + mesh + " -o " + dir + "/out.ply --smooth auto");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("noise level") != std::string::npos);
    CHECK(number_after(r.output, "noise level ") > 0);
    CHECK(number_after(r.output, "smoothing widths (auto): normals ") > 0);
    const std::string ply = read_file(dir + "/out.ply");
    const std::string header = ply.substr(0, ply.find("end_header"));
    INFO(header);
    CHECK(header.find("comment smoothing normals ") != std::string::npos);
    CHECK(header.find("(auto: noise sigma ") != std::string::npos);
    CHECK(number_after(header, "comment smoothing normals ") ==
          Approx(number_after(r.output, "smoothing widths (auto): normals ")).epsilon(1e-5));
}

TEST_CASE("kappa curvature without --smooth reports zero widths and no noise estimate",
          "[cli][curvature][smooth-auto]") {
    const std::string dir = test::temp_dir();
    const auto r = run_command(kExe + " curvature -o " + dir + "/out.ply");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("noise level") == std::string::npos);
    CHECK(r.output.find("smoothing widths: normals 0, curvature 0, dcurv 0") != std::string::npos);
    CHECK(read_file(dir + "/out.ply").find("comment smoothing normals 0 curvature 0 dcurv 0\n") != std::string::npos);
}

TEST_CASE("kappa curvature --smooth auto keeps explicit widths and leaves the CSV columns alone",
          "[cli][curvature][smooth-auto]") {
    const std::string dir = test::temp_dir();
    const std::string mesh = noisy_torus_file(dir);
    const auto r =
        run_command(kExe + " curvature " + mesh + " -o " + dir + "/out.csv --smooth auto --smooth-curvature 0.125");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("curvature 0.125,") != std::string::npos);
    CHECK(number_after(r.output, "smoothing widths (auto): normals ") > 0);
    const std::string csv = read_file(dir + "/out.csv");
    CHECK(csv.substr(0, csv.find('\n')) == "x,y,z,nx,ny,nz,k1,k2,d1x,d1y,d1z,d2x,d2y,d2z,a,b,c,d");

    const auto bad = run_command(kExe + " curvature " + mesh + " -o " + dir + "/out.csv --smooth sometimes");
    CHECK(bad.exit_code == 2);
    CHECK(bad.output.find("--smooth expects auto or off") != std::string::npos);
}

TEST_CASE("kappa curvature --help advises --smooth auto for noisy meshes", "[cli][curvature][smooth-auto]") {
    const auto r = run_command(kExe + " curvature --help");
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("--smooth auto|off") != std::string::npos);
    CHECK(r.output.find("--smooth auto") != std::string::npos);
}
