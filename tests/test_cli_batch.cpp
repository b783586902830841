// `kappa batch` end to end: the real executable on small manifests of the
// built-in model and generated meshes (128x96 images).
#include "test_shapes.h"
#include "test_support.h"

#include "geometry/mesh/primitives.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>
#include <string>
#include <utility>
#include <vector>

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

TEST_CASE("kappa batch: an output it cannot write fails that job alone, in one line, and leaves nothing behind",
          "[cli][batch]") {
    const std::string dir = temp_dir();
    write_file(dir + "/blocker", "a file where the job wants a folder\n");
    write_file(dir + "/jobs.txt",
               "-  out/a.png          --size 128x96\n"
               "-  blocker/b.png      --size 128x96\n"
               "-  blocker/c.csv\n"
               "-  out/d.png          --size 128x96 --view 90,20\n");
    const auto r = run_command(kExe + " batch -q " + dir + "/jobs.txt --failures " + dir + "/failed.txt 2>&1");
    INFO(r.output);
    CHECK(r.exit_code == 1);
    CHECK(r.output.find("4 jobs: 2 written, 0 skipped (output exists), 2 failed") != std::string::npos);
    CHECK(files_under(dir + "/out") == std::set<std::string>{"a.png", "d.png"});
    for (const char* name : {"b.png", "c.csv"}) {
        const std::string output = dir + "/blocker/" + name;
        INFO(name);
        // line N: OUTPUT: OUTPUT: cannot create its folder: (the system's reason)
        const size_t at = r.output.find(": " + output + ": cannot create its folder");
        CHECK(at != std::string::npos);
        CHECK(r.output.rfind("  line ", at) != std::string::npos);
    }
    CHECK(read_file(dir + "/blocker") == "a file where the job wants a folder\n");
    CHECK(kappa::test::count_lines(read_file(dir + "/failed.txt")) == 2);
    // No partial file anywhere.
    for (const auto& name : files_under(dir)) CHECK(name.find(".partial-") == std::string::npos);
}

TEST_CASE("kappa batch: a relative --xf in a manifest is read from the manifest's folder", "[cli][batch][xf]") {
    const std::string dir = temp_dir(), elsewhere = temp_dir();
    fs::create_directories(dir + "/views");
    // A torus about the origin (radius 1.4), seen along its axis from 4 units (a.xf) and from the side
    // (b.xf): rtsc .xf files hold the view matrix row by row.
    write_off(dir + "/torus.off", kappa::make_torus(1.0f, 0.4f, 32, 16));
    write_file(dir + "/views/a.xf", "1 0 0 0\n0 1 0 0\n0 0 1 -4\n0 0 0 1\n");
    write_file(dir + "/views/b.xf", "0 0 -1 0\n0.5 0.866025 0 0\n0.866025 -0.5 0 -4\n0 0 0 1\n");
    write_file(dir + "/jobs.txt",
               "torus.off  out/a.png --size 128x96 --shading none --xf views/a.xf\n"
               "torus.off  out/b.png --size 128x96 --shading none --xf=views/b.xf\n"
               "torus.off  out/default.png --size 128x96 --shading none\n");
    // Run from another folder: the paths must not be taken from the working directory.
    const auto r = run_command("cd " + elsewhere + " && " + kExe + " batch -q " + dir + "/jobs.txt 2>&1");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("3 jobs: 3 written") != std::string::npos);
    CHECK(files_under(elsewhere).empty());
    for (const std::string view : {"a", "b"}) {
        INFO(view);
        REQUIRE(run_command(kExe + " render -q " + dir + "/torus.off --size 128x96 --shading none --xf " + dir +
                            "/views/" + view + ".xf -o " + dir + "/single-" + view + ".png")
                    .exit_code == 0);
        CHECK(read_file(dir + "/out/" + view + ".png") == read_file(dir + "/single-" + view + ".png"));
        // The viewpoint was used: not the default drawing.
        CHECK(read_file(dir + "/out/" + view + ".png") != read_file(dir + "/out/default.png"));
    }
    CHECK(read_file(dir + "/out/a.png") != read_file(dir + "/out/b.png"));
}

TEST_CASE("kappa batch computes the fields again when consecutive jobs differ in crease angle, detail or curvature "
          "options",
          "[cli][batch][cache]") {
    // A torus beside a box: sharp edges for --crease-angle, curvature for the rest.
    const std::string dir = temp_dir();
    kappa::Mesh shape = kappa::make_torus(1.0f, 0.4f, 48, 24);
    kappa::test::append(shape, kappa::test::box({1.6f, -0.5f, -0.5f}, {2.4f, 0.5f, 0.5f}));
    write_off(dir + "/shape.off", shape);
    // One mesh, each job differing from the one before it in one option of the preparation.
    const std::string view = " --size 128x96 --view 20,30 --shading lambert";
    const std::vector<std::pair<std::string, std::string>> jobs = {
        {"crease.png", view + " --crease-angle 30"},
        {"no-crease.png", view + " --crease-angle off"},
        {"detail-off.png", view + " --crease-angle off --detail off"},
        {"smoothed.png", view + " --crease-angle off --detail off --smooth-curvature 0.1"},
        {"jet.png", view + " --crease-angle off --detail off --smooth-curvature 0.1 --estimator jet"},
        {"raw.csv", ""},
        {"smoothed.csv", " --smooth-curvature 0.1"},
        {"jet.csv", " --smooth-curvature 0.1 --estimator jet"},
        {"auto.csv", " --smooth auto --estimator jet"},
    };
    std::string manifest;
    for (const auto& [output, options] : jobs) manifest += "shape.off out/" + output + options + "\n";
    write_file(dir + "/jobs.txt", manifest);
    const auto r = run_command(kExe + " batch -q " + dir + "/jobs.txt 2>&1");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    std::string previous;
    for (const auto& [output, options] : jobs) {
        const bool render = output.find(".png") != std::string::npos;
        const std::string single = dir + "/single-" + output;
        REQUIRE(run_command(kExe + (render ? " render" : " curvature") + " -q " + dir + "/shape.off -o " + single +
                            options)
                    .exit_code == 0);
        const std::string bytes = read_file(dir + "/out/" + output);
        INFO(output << options);
        CHECK(!bytes.empty());
        CHECK(bytes == read_file(single));  // not the previous job's fields
        if (output != "raw.csv") CHECK(bytes != previous);  // the option changes the result
        previous = bytes;
    }
}

namespace {

// Whether a file is a whole PNG: it ends with the IEND chunk (a write cut short does not).
bool complete_png(const std::string& path) {
    const std::string bytes = read_file(path);
    static const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
    return bytes.size() > 8 + iend.size() && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0 &&
           bytes.compare(bytes.size() - iend.size(), iend.size(), iend) == 0;
}

}  // namespace

TEST_CASE("kappa batch killed while writing leaves no output a rerun would skip, and the rerun finishes the rest",
          "[cli][batch][interrupted]") {
    // A small job, a large image (its PNG takes tens of milliseconds to write), a small job.
    const std::string dir = temp_dir();
    write_file(dir + "/jobs.txt",
               "-  out/first.png --size 128x96 --shading none\n"
               "-  out/large.png --size 2400x1800 --shading none --lines contours\n"
               "-  out/last.png  --size 128x96 --shading none --view 90,20\n");
    const std::string command = kExe + " batch -q " + dir + "/jobs.txt";
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", ("exec " + command + " >/dev/null 2>&1").c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    // Kill it (SIGKILL: no chance to tidy up) the moment any file of the large job appears.
    bool seen = false;
    for (int i = 0; i < 200000 && !seen; ++i) {
        for (const auto& name : files_under(dir + "/out")) seen |= name.rfind("large", 0) == 0;
        if (!seen) usleep(100);
    }
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    REQUIRE(seen);
    REQUIRE(WIFSIGNALED(status));  // killed, not finished
    // What the interrupted run left under the outputs' own names is whole.
    size_t whole = 0;
    for (const char* name : {"first.png", "large.png", "last.png"}) {
        const std::string path = dir + "/out/" + name;
        if (!fs::exists(path)) continue;
        INFO(name << " after the kill");
        CHECK(complete_png(path));
        ++whole;
    }
    CHECK(complete_png(dir + "/out/first.png"));
    // The rerun skips exactly those and writes the others, whole.
    const auto r = run_command(command + " 2>&1");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("3 jobs: " + std::to_string(3 - whole) + " written, " + std::to_string(whole) + " skipped") !=
          std::string::npos);
    for (const char* name : {"first.png", "large.png", "last.png"}) {
        INFO(name << " after the rerun");
        CHECK(complete_png(dir + "/out/" + name));
    }
}
