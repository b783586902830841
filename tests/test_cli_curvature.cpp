// `kappa curvature` end to end: the real executable, real files.
#include "test_shapes.h"
#include "test_support.h"

#include "geometry/io/mesh_io.h"
#include "geometry/mesh/primitives.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace kappa;
using kappa::test::count_lines;
using kappa::test::run_command;

namespace {

const std::string kExe = KAPPA_EXE;

using kappa::test::write_off;

std::vector<std::vector<double>> read_csv_rows(const std::string& path, std::string& header) {
    std::ifstream f(path);
    std::getline(f, header);
    std::vector<std::vector<double>> rows;
    std::string line;
    while (std::getline(f, line)) {
        std::vector<double> row;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
        rows.push_back(row);
    }
    return rows;
}

}  // namespace

TEST_CASE("kappa curvature writes the CSV of conventions.md", "[cli][curvature]") {
    const std::string dir = kappa::test::temp_dir();
    const Mesh sphere = make_icosphere(2.0f, 3);
    write_off(dir + "/sphere.off", sphere);
    const auto r = run_command(kExe + " curvature " + dir + "/sphere.off -o " + dir + "/out.csv");
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("642 vertices, 1280 faces") != std::string::npos);
    std::string header;
    const auto rows = read_csv_rows(dir + "/out.csv", header);
    CHECK(header == "x,y,z,nx,ny,nz,k1,k2,d1x,d1y,d1z,d2x,d2y,d2z,a,b,c,d");
    REQUIRE(rows.size() == sphere.positions.size());
    for (size_t i = 0; i < rows.size(); ++i) {
        REQUIRE(rows[i].size() == 18);
        // Input order preserved, positions round-trip through %.9g exactly.
        CHECK(float(rows[i][0]) == sphere.positions[i].x);
        CHECK(float(rows[i][2]) == sphere.positions[i].z);
        CHECK(rows[i][6] == Approx(0.5).epsilon(1e-4));  // k1 = 1/R
        CHECK(rows[i][7] == Approx(0.5).epsilon(1e-4));
        CHECK(rows[i][3] * sphere.positions[i].x + rows[i][4] * sphere.positions[i].y +
                  rows[i][5] * sphere.positions[i].z == Approx(2.0).epsilon(1e-5));  // outward normal
    }
}

TEST_CASE("kappa curvature writes a PLY that reads back", "[cli][curvature]") {
    const std::string dir = kappa::test::temp_dir();
    const Mesh torus = make_torus(1.0f, 0.3f, 40, 16);
    write_off(dir + "/torus.off", torus);
    for (const std::string fmt : {"", " --format ply-ascii"}) {
        const auto r = run_command(kExe + " curvature " + dir + "/torus.off -o " + dir + "/out.ply" + fmt);
        REQUIRE(r.exit_code == 0);
        const Mesh back = load_mesh(dir + "/out.ply");
        CHECK(back.positions.size() == torus.positions.size());
        CHECK(back.faces.size() == torus.faces.size());
        const std::string bytes = kappa::test::read_file(dir + "/out.ply");
        for (const char* prop : {"property float k1", "property float k2", "property float d1x", "property float a",
                                 "property float d", "property uchar flags"})
            CHECK(bytes.find(prop) != std::string::npos);
    }
}

TEST_CASE("kappa curvature output does not depend on the thread count", "[cli][curvature][determinism]") {
    const std::string dir = kappa::test::temp_dir();
    REQUIRE(run_command(kExe + " curvature --threads 1 --smooth-curvature 0.02 -o " + dir + "/one.csv").exit_code == 0);
    REQUIRE(run_command(kExe + " curvature --threads 2 --smooth-curvature 0.02 -o " + dir + "/two.csv").exit_code == 0);
    const std::string one = kappa::test::read_file(dir + "/one.csv");
    CHECK(count_lines(one) > 10000);  // the built-in model
    CHECK(one == kappa::test::read_file(dir + "/two.csv"));
}

TEST_CASE("kappa curvature reports bad input on one line with a non-zero exit", "[cli][curvature][errors]") {
    const std::string dir = kappa::test::temp_dir();
    SECTION("missing mesh") {
        const auto r = run_command(kExe + " curvature " + dir + "/nope.ply -o " + dir + "/out.csv");
        CHECK(r.exit_code == 1);
        CHECK(count_lines(r.output) == 1);
        CHECK(r.output.find("nope.ply") != std::string::npos);
    }
    SECTION("no output") {
        const auto r = run_command(kExe + " curvature");
        CHECK(r.exit_code == 2);
        CHECK(count_lines(r.output) == 1);
    }
    SECTION("unknown output format") {
        const auto r = run_command(kExe + " curvature -o " + dir + "/out.xyz");
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("out.xyz") != std::string::npos);
    }
    SECTION("unwritable output, found before the mesh is read") {
        const auto r = run_command(kExe + " curvature " + dir + "/nope.ply -o " + dir + "/no/such/dir/out.csv");
        CHECK(r.exit_code == 1);
        CHECK(count_lines(r.output) == 1);
        CHECK(r.output.find("out.csv") != std::string::npos);
        CHECK(r.output.find("no such folder") != std::string::npos);  // not the missing mesh
    }
    SECTION("unknown estimator, with the valid names") {
        const auto r = run_command(kExe + " curvature -o " + dir + "/out.csv --estimator jets");
        CHECK(r.exit_code == 2);
        CHECK(count_lines(r.output) == 1);
        CHECK(r.output.find("points-normals-fit") != std::string::npos);
    }
    SECTION("negative smoothing width") {
        const auto r = run_command(kExe + " curvature -o " + dir + "/out.csv --smooth-normals -1");
        CHECK(r.exit_code == 2);
    }
}

TEST_CASE("kappa curvature --help documents the columns and options", "[cli][curvature]") {
    const auto r = run_command(kExe + " curvature --help");
    CHECK(r.exit_code == 0);
    for (const char* s : {"x,y,z,nx,ny,nz,k1,k2,d1x,d1y,d1z,d2x,d2y,d2z,a,b,c,d", "--smooth-normals",
                          "--smooth-curvature", "--smooth-dcurv", "--format", "--threads", "-o", "--estimator",
                          "rusinkiewicz", "tensor-averaging", "normal-fit", "points-normals-fit"})
        CHECK(r.output.find(s) != std::string::npos);
}

TEST_CASE("kappa curvature of a mesh with no faces says nothing could be estimated and writes zeros, never -0",
          "[cli][curvature]") {
    const std::string dir = kappa::test::temp_dir();
    kappa::test::write_file(dir + "/points.ply",
                            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                            "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n"
                            "0 0 0\n1 0 0\n0 1 0\n");
    const auto r = run_command(kExe + " curvature " + dir + "/points.ply -o " + dir + "/out.csv");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("every vertex is flagged") != std::string::npos);
    CHECK(r.output.find("(unflagged vertices)") == std::string::npos);
    const std::string csv = kappa::test::read_file(dir + "/out.csv");
    CHECK(csv.find("-0,") == std::string::npos);
    CHECK(csv.find("-0\n") == std::string::npos);
    CHECK(count_lines(csv) == 4);  // header and three rows
}

TEST_CASE("kappa curvature --estimator: the default is rusinkiewicz, every other one writes its own values",
          "[cli][curvature][estimators]") {
    const std::string dir = kappa::test::temp_dir();
    REQUIRE(run_command(kExe + " curvature -q -o " + dir + "/default.csv").exit_code == 0);
    const std::string def = kappa::test::read_file(dir + "/default.csv");
    REQUIRE(run_command(kExe + " curvature -q --estimator rusinkiewicz -o " + dir + "/r.csv").exit_code == 0);
    CHECK(kappa::test::read_file(dir + "/r.csv") == def);
    for (const char* name : {"jet", "tensor-averaging", "normal-fit", "points-normals-fit"}) {
        INFO(name);
        const std::string path = dir + "/" + name + ".csv";
        REQUIRE(run_command(kExe + " curvature -q --estimator " + name + " -o " + path).exit_code == 0);
        const std::string out = kappa::test::read_file(path);
        CHECK(count_lines(out) == count_lines(def));
        CHECK(out != def);
        CHECK(out.find("nan") == std::string::npos);
        CHECK(out.find("inf") == std::string::npos);
    }
}

TEST_CASE("kappa curvature --estimator: every estimator's k1 and k2 are close to a torus's exact curvature",
          "[cli][curvature][estimators]") {
    // Torus R = 1, r = 0.4 around z: k1 = 1/r along the tube, k2 =
    // cos v / (R + r cos v) = (rho - R) / (r rho) along the big circle
    // (rho = distance from the axis). Relative RMS error over the vertices;
    // k = 0 gives 1, a sign swap about 2. Measured on this 90 x 36 torus
    // (printed by INFO, 2026-11-26): rusinkiewicz 0.25%, jet 0.58%,
    // tensor-averaging 0.45%, normal-fit 0.12%, points-normals-fit 1.35%;
    // bounds with margins of about 1.5x.
    const std::string dir = kappa::test::temp_dir();
    const double R = 1.0, r = 0.4;
    const Mesh torus = make_torus(float(R), float(r), 90, 36);
    write_off(dir + "/torus.off", torus);
    struct Bound {
        const char* name;
        double error;
    };
    for (const Bound& b : {Bound{"rusinkiewicz", 0.004}, Bound{"jet", 0.009}, Bound{"tensor-averaging", 0.007},
                           Bound{"normal-fit", 0.002}, Bound{"points-normals-fit", 0.02}}) {
        INFO(b.name);
        const std::string out = dir + "/" + b.name + ".csv";
        const auto run = run_command(kExe + " curvature -q " + dir + "/torus.off --estimator " + b.name + " -o " + out);
        INFO(run.output);
        REQUIRE(run.exit_code == 0);
        std::string header;
        const auto rows = read_csv_rows(out, header);
        REQUIRE(rows.size() == torus.positions.size());
        double err = 0, ref = 0;
        for (const auto& row : rows) {
            const double rho = std::hypot(row[0], row[1]);
            const double k1 = 1 / r, k2 = (rho - R) / (r * rho);
            err += (row[6] - k1) * (row[6] - k1) + (row[7] - k2) * (row[7] - k2);
            ref += k1 * k1 + k2 * k2;
        }
        const double relative = std::sqrt(err / ref);
        INFO("relative RMS error of k1, k2: " << relative);
        CHECK(relative < b.error);
    }
}
