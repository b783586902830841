// The `kappa` dispatcher run as a real process: help, version, unknown
// commands and options, global --threads.
#include "test_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

using kappa::test::count_lines;
using kappa::test::run_command;

namespace {

const std::string kExe = KAPPA_EXE;

// Command names listed under "Commands:" in `kappa --help`.
std::vector<std::string> listed_commands(const std::string& help) {
    std::vector<std::string> names;
    std::istringstream in(help);
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        if (line == "Commands:") {
            inside = true;
        } else if (inside) {
            if (line.rfind("  ", 0) != 0) break;
            std::istringstream words(line);
            std::string name;
            words >> name;
            names.push_back(name);
        }
    }
    return names;
}

}  // namespace

TEST_CASE("kappa --help lists the commands, each with its own help", "[cli][main]") {
    const auto r = run_command(kExe + " --help");
    REQUIRE(r.exit_code == 0);
    const auto names = listed_commands(r.output);
    CHECK(std::find(names.begin(), names.end(), "info") != names.end());
    for (const char* option : {"--threads", "--version", "--help"}) CHECK(r.output.find(option) != std::string::npos);
    for (const auto& name : names) {
        INFO(name);
        const auto sub = run_command(kExe + " " + name + " --help");
        CHECK(sub.exit_code == 0);
        CHECK(sub.output.rfind("Usage: kappa " + name, 0) == 0);
        CHECK(sub.output.find("--help") != std::string::npos);
        // `kappa help NAME` is the same text.
        CHECK(run_command(kExe + " help " + name).output == sub.output);
    }
}

TEST_CASE("kappa --version prints one line", "[cli][main]") {
    const auto r = run_command(kExe + " --version");
    CHECK(r.exit_code == 0);
    CHECK(r.output.rfind("kappa ", 0) == 0);
    CHECK(count_lines(r.output) == 1);
}

TEST_CASE("kappa without a command prints usage and fails", "[cli][main]") {
    const auto r = run_command(kExe);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("Usage: kappa") != std::string::npos);
}

TEST_CASE("unknown commands and options: one line, exit 2", "[cli][main]") {
    SECTION("unknown command, with a suggestion") {
        const auto r = run_command(kExe + " inf");
        CHECK(r.exit_code == 2);
        CHECK(count_lines(r.output) == 1);
        CHECK(r.output.find("unknown command 'inf'") != std::string::npos);
        CHECK(r.output.find("did you mean 'info'") != std::string::npos);
        CHECK(r.output.find("kappa --help") != std::string::npos);
    }
    SECTION("unknown global option") {
        const auto r = run_command(kExe + " --frobnicate info");
        CHECK(r.exit_code == 2);
        CHECK(count_lines(r.output) == 1);
        CHECK(r.output.find("'--frobnicate'") != std::string::npos);
    }
    SECTION("unknown option of a command") {
        const auto r = run_command(kExe + " info --frobnicate");
        CHECK(r.exit_code == 2);
        CHECK(count_lines(r.output) == 1);
        CHECK(r.output.rfind("kappa info: unknown option '--frobnicate'", 0) == 0);
        CHECK(r.output.find("kappa info --help") != std::string::npos);
    }
    SECTION("help for an unknown command") {
        const auto r = run_command(kExe + " help nothing");
        CHECK(r.exit_code == 2);
        CHECK(count_lines(r.output) == 1);
    }
}

// The worker count `kappa curvature` reports ("worker threads: N", the
// kappa::thread_count() that parallel_for splits its work by); -1 if none.
int reported_threads(const std::string& output) {
    const std::string tag = "worker threads: ";
    const size_t at = output.find(tag);
    if (at == std::string::npos) return -1;
    return std::atoi(output.c_str() + at + tag.size());
}

TEST_CASE("global and per-command --threads", "[cli][main]") {
    CHECK(run_command(kExe + " --threads 1 info --no-curvature").exit_code == 0);
    CHECK(run_command(kExe + " --threads=2 info --no-curvature").exit_code == 0);
    CHECK(run_command(kExe + " info --no-curvature --threads 1").exit_code == 0);
    // The count takes effect: 1 and 3 workers whichever way it is given, and
    // by default (or 0) one per hardware thread, as std::thread counts them here.
    const std::string dir = kappa::test::temp_dir();
    const std::string curvature = " curvature -o " + dir + "/out.csv";
    const int hardware = int(std::max(1u, std::thread::hardware_concurrency()));
    const std::vector<std::pair<std::string, int>> runs = {
        {curvature + " --threads 1", 1},   {curvature + " --threads 3", 3}, {" --threads 1" + curvature, 1},
        {" --threads=3" + curvature, 3},   {curvature, hardware},           {curvature + " --threads 0", hardware},
    };
    for (const auto& [args, expected] : runs) {
        const auto r = run_command(kExe + args);
        INFO(args << ": " << r.output);
        REQUIRE(r.exit_code == 0);
        CHECK(reported_threads(r.output) == expected);
    }
    for (const char* bad : {" --threads x info", " --threads -1 info", " info --threads", " --threads"}) {
        INFO(bad);
        const auto r = run_command(kExe + bad);
        CHECK(r.exit_code == 2);
        CHECK(count_lines(r.output) == 1);
        CHECK(r.output.find("--threads expects") != std::string::npos);
    }
}

TEST_CASE("negative vector values reach the option, bad ones are named", "[cli][main]") {
    const auto names = listed_commands(run_command(kExe + " --help").output);
    if (std::find(names.begin(), names.end(), "render") == names.end()) return;  // built without the renderer
    // Parsing stops at --help, after --eye took "0,-2.6,1.85" as its value.
    CHECK(run_command(kExe + " render --eye 0,-2.6,1.85 --help").exit_code == 0);
    CHECK(run_command(kExe + " render --eye=0,-2.6,1.85 --help").exit_code == 0);
    const auto bad = run_command(kExe + " render --eye 0,-2.6 --help");
    CHECK(bad.exit_code == 2);
    CHECK(bad.output == "kappa render: --eye expects X,Y,Z, got '0,-2.6'\n");
    const auto size = run_command(kExe + " render --size 12");
    CHECK(size.exit_code == 2);
    CHECK(size.output == "kappa render: --size expects WxH, got '12'\n");
}
