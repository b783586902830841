// `kappa batch` end to end: the real executable on small manifests of the
// built-in model and generated meshes (128x96 images).
#include "test_shapes.h"
#include "test_support.h"

#include "geometry/mesh/primitives.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>

using kappa::test::read_file;
using kappa::test::run_command;
using kappa::test::temp_dir;
using kappa::test::write_file;
using kappa::test::write_off;
namespace fs = std::filesystem;

namespace {

const std::string kExe = KAPPA_EXE;

// dir/jobs.txt: three meshes (built-in, a torus, a sphere) x two views, a
// curvature job, in an order that interleaves the meshes.
std::string write_manifest(const std::string& dir) {
    write_off(dir + "/torus.off", kappa::make_torus(1.0f, 0.4f, 32, 16));
    write_off(dir + "/sphere.off", kappa::make_uv_sphere(1.0f, 24, 12));
    write_file(dir + "/jobs.txt",
               "# mesh output options\n"
               "-           out/default-0.png --view 0,20 --size 128x96\n"
               "torus.off   out/torus-0.png   --view 0,40 --size 128x96 --shading none\n"
               "\n"
               "sphere.off  out/sphere-0.png  --size 128x96\n"
               "-           out/default-1.svg --view 90,20 --size 128x96 --shading none\n"
               "torus.off   out/torus-1.png   --view 90,40 --size 128x96 --shading none\n"
               "sphere.off  \"out/sphere 1.png\" --view 45,0 --size 128x96\n"
               "torus.off   out/torus.csv\n");
    return dir + "/jobs.txt";
}

std::set<std::string> files_under(const std::string& dir) {
    std::set<std::string> names;
    if (!fs::exists(dir)) return names;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) names.insert(e.path().filename().string());
    return names;
}

}  // namespace

TEST_CASE("kappa batch writes every job of a manifest, each the same as the single command", "[cli][batch]") {
    const std::string dir = temp_dir(), manifest = write_manifest(dir);
    const auto r = run_command(kExe + " batch " + manifest + " 2>&1");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(files_under(dir + "/out") == std::set<std::string>{"default-0.png", "default-1.svg", "sphere-0.png",
                                                             "sphere 1.png", "torus-0.png", "torus-1.png",
                                                             "torus.csv"});
    CHECK(r.output.find("7 jobs: 7 written, 0 skipped (output exists), 0 failed") != std::string::npos);
    CHECK(r.output.find("ETA") != std::string::npos);  // progress on stderr
    // The same bytes as kappa render / kappa curvature with the job's options.
    REQUIRE(run_command(kExe + " render " + dir + "/torus.off -o " + dir + "/single.png -q --view 90,40 "
                        "--size 128x96 --shading none").exit_code == 0);
    CHECK(read_file(dir + "/single.png") == read_file(dir + "/out/torus-1.png"));
    REQUIRE(run_command(kExe + " render -o " + dir + "/single.svg -q --view 90,20 --size 128x96 --shading none")
                .exit_code == 0);
    CHECK(read_file(dir + "/single.svg") == read_file(dir + "/out/default-1.svg"));
    REQUIRE(run_command(kExe + " curvature " + dir + "/torus.off -o " + dir + "/single.csv -q").exit_code == 0);
    CHECK(read_file(dir + "/single.csv") == read_file(dir + "/out/torus.csv"));
}

TEST_CASE("kappa batch skips outputs that exist, and --force rewrites them", "[cli][batch]") {
    const std::string dir = temp_dir(), manifest = write_manifest(dir);
    fs::create_directories(dir + "/out");
    write_file(dir + "/out/torus-0.png", "not a png");  // an existing output: kept as it is
    auto r = run_command(kExe + " batch -q " + manifest + " 2>&1");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("7 jobs: 6 written, 1 skipped (output exists), 0 failed") != std::string::npos);
    CHECK(read_file(dir + "/out/torus-0.png") == "not a png");
    CHECK(r.output.find("ETA") == std::string::npos);  // -q: no progress
    r = run_command(kExe + " batch -q " + manifest + " 2>&1");
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("7 jobs: 0 written, 7 skipped") != std::string::npos);
    r = run_command(kExe + " batch -q --force " + manifest + " 2>&1");
    CHECK(r.output.find("7 jobs: 7 written, 0 skipped") != std::string::npos);
    CHECK(read_file(dir + "/out/torus-0.png") != "not a png");
    // No partial files left behind.
    for (const auto& name : files_under(dir + "/out")) CHECK(name.find(".partial-") == std::string::npos);
}

TEST_CASE("kappa batch --shard I/N splits the manifest by mesh, the shards covering it once", "[cli][batch]") {
    const std::string dir = temp_dir(), manifest = write_manifest(dir);
    std::set<std::string> all;
    std::vector<std::set<std::string>> shards;
    for (int i = 0; i < 2; ++i) {
        const std::string out = dir + "/out";
        const auto r = run_command(kExe + " batch -q --force " + manifest + " --shard " + std::to_string(i) + "/2 2>&1");
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        shards.push_back(files_under(out));
        fs::rename(out, dir + "/shard" + std::to_string(i));
        all.insert(shards.back().begin(), shards.back().end());
    }
    // Meshes in order of first appearance: built-in (0), torus (1), sphere (2).
    CHECK(shards[0] == std::set<std::string>{"default-0.png", "default-1.svg", "sphere-0.png", "sphere 1.png"});
    CHECK(shards[1] == std::set<std::string>{"torus-0.png", "torus-1.png", "torus.csv"});
    CHECK(all.size() == 7);
    // Bad shards are usage errors.
    for (const char* bad : {"2/2", "-1/2", "0/0", "1", "a/b"}) {
        const auto r = run_command(kExe + " batch " + manifest + " --shard " + bad + " 2>&1");
        INFO(bad << ": " << r.output);
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("--shard expects I/N with 0 <= I < N") != std::string::npos);
    }
}

TEST_CASE("kappa batch reports every failure in one line and carries on", "[cli][batch]") {
    const std::string dir = temp_dir();
    write_file(dir + "/garbage.ply", "ply\nformat nonsense\n");
    write_file(dir + "/jobs.txt",
               "missing.ply out/a.png --size 128x96\n"
               "-           out/b.png --size 128x96 --line-width abc\n"
               "garbage.ply out/c.png --size 128x96\n"
               "-           out/d.png --size 128x96\n"
               "missing.ply out/e.csv\n");
    const auto r = run_command(kExe + " batch -q " + dir + "/jobs.txt --failures " + dir + "/failed.txt 2>&1");
    INFO(r.output);
    CHECK(r.exit_code == 1);
    CHECK(files_under(dir + "/out") == std::set<std::string>{"d.png"});
    CHECK(r.output.find("5 jobs: 1 written, 0 skipped (output exists), 4 failed") != std::string::npos);
    const std::string missing = dir + "/missing.ply: no such file";
    CHECK(r.output.find("line 1: " + dir + "/out/a.png: " + missing + "\n") != std::string::npos);
    CHECK(r.output.find("line 2: " + dir + "/out/b.png: --line-width expects a number in [0.1, 64], got 'abc'\n") !=
          std::string::npos);
    CHECK(r.output.find("line 3: " + dir + "/out/c.png: " + dir + "/garbage.ply: ") != std::string::npos);
    CHECK(r.output.find("line 5: " + dir + "/out/e.csv: " + missing + "\n") != std::string::npos);
    // The failures file: one line each, in manifest order.
    const std::string failed = read_file(dir + "/failed.txt");
    CHECK(kappa::test::count_lines(failed) == 4);
    CHECK(failed.find(dir + "/jobs.txt:1: ") == 0);
    // A rerun retries only the failures.
    const auto again = run_command(kExe + " batch -q " + dir + "/jobs.txt 2>&1");
    CHECK(again.output.find("5 jobs: 0 written, 1 skipped (output exists), 4 failed") != std::string::npos);
}

TEST_CASE("kappa batch refuses a malformed or missing manifest in one line", "[cli][batch]") {
    const std::string dir = temp_dir();
    write_file(dir + "/jobs.txt", "-  out/a.png\n-  \"out/b.png --size 12x12\n");
    auto r = run_command(kExe + " batch " + dir + "/jobs.txt 2>&1");
    CHECK(r.exit_code == 1);
    CHECK(r.output == "kappa: " + dir + "/jobs.txt:2: unterminated quote\n");
    write_file(dir + "/jobs.txt", "-  out/a.txt\n");
    r = run_command(kExe + " batch " + dir + "/jobs.txt 2>&1");
    CHECK(r.exit_code == 1);
    CHECK(r.output.find("jobs.txt:1: cannot tell the output format of 'out/a.txt'") != std::string::npos);
    r = run_command(kExe + " batch " + dir + "/none.txt 2>&1");
    CHECK(r.exit_code == 1);
    CHECK(r.output == "kappa: " + dir + "/none.txt: cannot open the manifest\n");
    CHECK(!fs::exists(dir + "/out"));
}
