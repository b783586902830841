// The option parser of app/cli_options.h, tested in-process. The app sources
// are not a library, so its one source file is compiled into this test here.
#include "../app/cli_options.cpp"

#include "geometry/parallel/parallel.h"

#include <catch2/catch.hpp>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace kappa::cli;

namespace {

// argv from words; argv[0] is the command name.
struct Args {
    std::vector<std::string> words;
    std::vector<char*> argv;
    explicit Args(std::vector<std::string> w) : words(std::move(w)) {
        for (auto& s : words) argv.push_back(s.data());
        argv.push_back(nullptr);
    }
    int argc() const { return int(words.size()); }
    char** data() { return argv.data(); }
};

// Parses, returning "" on success or the UsageError message.
std::string parse(Parser& p, std::vector<std::string> words) {
    words.insert(words.begin(), p.command());
    Args args(words);
    try {
        p.parse_or_throw(args.argc(), args.data());
        return "";
    } catch (const UsageError& e) {
        return e.what();
    }
}

}  // namespace

TEST_CASE("value parsers", "[cli][options]") {
    CHECK(*parse_number("2.5") == 2.5);
    CHECK(*parse_number("-1e-3") == -1e-3);
    CHECK(*parse_number("+4") == 4.0);
    for (const char* bad : {"", "abc", "1.5x", "nan", "inf", "1,2", "+", "+-1", " 1"}) CHECK_FALSE(parse_number(bad));

    CHECK(*parse_int("12") == 12);
    CHECK(*parse_int("-3") == -3);
    for (const char* bad : {"1.5", "99999999999", "", "x"}) CHECK_FALSE(parse_int(bad));

    const auto v = parse_vec3("0,-2.6,1.85");
    REQUIRE(v);
    CHECK(v->x == 0.0f);
    CHECK(v->y == Approx(-2.6f));
    CHECK(v->z == Approx(1.85f));
    CHECK(parse_vec3(" 1, 2 ,3"));
    for (const char* bad : {"1,2", "1,2,3,4", "a,b,c", "1,,3", ""}) CHECK_FALSE(parse_vec3(bad));

    CHECK(*parse_size("1920x1080") == glm::ivec2(1920, 1080));
    for (const char* bad : {"12", "0x5", "-3x4", "12x", "x12", "1.5x2"}) CHECK_FALSE(parse_size(bad));

    CHECK(split("a,,b", ',') == std::vector<std::string>{"a", "", "b"});
    CHECK(closest_match("--sise", {"--size", "--eye"}) == "--size");
    CHECK(closest_match("--zzzzzz", {"--size", "--eye"}).empty());
}

TEST_CASE("options take the next argument as value, even when it starts with '-'", "[cli][options]") {
    glm::vec3 eye(0), up(0, 1, 0);
    float fov = 30;
    Parser p("render", "", "");
    p.vec3("--eye", eye, "").vec3("--up", up, "").number("--fov", fov, "", 1, 179);
    CHECK(parse(p, {"--eye", "0,-2.6,1.85", "--up=0,0,-1", "--fov", "27.5"}).empty());
    CHECK(eye.y == Approx(-2.6f));
    CHECK(up.z == -1.0f);
    CHECK(fov == 27.5f);
    CHECK(p.seen("--eye"));
}

TEST_CASE("bad values: one message naming the option, the expectation and the value", "[cli][options]") {
    glm::ivec2 size(0);
    float width = 1, fov = 30;
    int n = 0;
    Parser p("render", "", "");
    p.size("--size", size, "").number("--line-width", width, "", 0.0).number("--fov", fov, "", 1, 179);
    p.integer("--count", n, "", 1);
    CHECK(parse(p, {"--size", "12"}) == "kappa render: --size expects WxH, got '12'");
    CHECK(parse(p, {"--line-width", "-1"}) == "kappa render: --line-width expects a number >= 0, got '-1'");
    CHECK(parse(p, {"--fov", "200"}) == "kappa render: --fov expects a number in [1, 179], got '200'");
    CHECK(parse(p, {"--count", "0"}) == "kappa render: --count expects an integer >= 1, got '0'");
    CHECK(parse(p, {"--fov"}) == "kappa render: --fov expects a number in [1, 179], got nothing");
}

TEST_CASE("unknown options, flags, positionals", "[cli][options]") {
    std::string mesh, out;
    bool fade = false;
    Parser p("render", "[MESH] -o OUT.png", "");
    p.positional("MESH", mesh, "", false).text("-o,--output", out, "", "FILE").flag("--fade", fade, "");

    const std::string unknown = parse(p, {"--outptu", "x.png"});
    CHECK(unknown.rfind("kappa render: unknown option '--outptu'", 0) == 0);
    CHECK(unknown.find("did you mean '--output'") != std::string::npos);
    CHECK(unknown.find("kappa render --help") != std::string::npos);

    CHECK(parse(p, {"bunny.ply", "-o", "a.png", "--fade"}).empty());
    CHECK(mesh == "bunny.ply");
    CHECK(out == "a.png");
    CHECK(fade);
    CHECK(parse(p, {"--output=b.png"}).empty());
    CHECK(out == "b.png");
    CHECK(parse(p, {"--fade=yes"}).find("--fade takes no value") != std::string::npos);
    CHECK(parse(p, {"a.ply", "b.ply"}).find("unexpected argument 'b.ply'") != std::string::npos);
    // After "--" everything is positional.
    CHECK(parse(p, {"--", "-weird-name.ply"}).empty());
    CHECK(mesh == "-weird-name.ply");

    std::string required;
    Parser q("curvature", "MESH", "");
    q.positional("MESH", required, "", true);
    CHECK(parse(q, {}).rfind("kappa curvature: missing MESH", 0) == 0);
}

TEST_CASE("choices, enums and comma lists", "[cli][options]") {
    enum class Shading { None, Lambert, Toon };
    Shading shading = Shading::Lambert;
    std::string colormap = "none";
    std::vector<std::string> lines{"contours", "suggestive"};
    Parser p("render", "", "");
    p.choice("--shading", shading, {{"none", Shading::None}, {"lambert", Shading::Lambert}, {"toon", Shading::Toon}},
             "")
        .choice("--colormap", colormap, {"none", "k1", "k2"}, "")
        .choice_list("--lines", lines, {"contours", "suggestive", "boundaries", "none"}, "");
    CHECK(parse(p, {"--shading", "toon", "--colormap", "k2", "--lines", "boundaries,contours"}).empty());
    CHECK(shading == Shading::Toon);
    CHECK(colormap == "k2");
    CHECK(lines == std::vector<std::string>{"boundaries", "contours"});
    CHECK(parse(p, {"--shading", "phong"}) ==
          "kappa render: --shading expects one of none, lambert, toon, got 'phong'");
    CHECK(parse(p, {"--lines", "contours,bogus"}).find("expects a comma list of") != std::string::npos);
    CHECK(parse(p, {"--lines", "contours,contours"}).find("expects a comma list of") != std::string::npos);
    // Help shows every choice.
    const std::string help = p.help();
    for (const char* word : {"none|lambert|toon", "none|k1|k2", "boundaries", "--help"})
        CHECK(help.find(word) != std::string::npos);
}

TEST_CASE("threads option sets the worker count, help stops parsing", "[cli][options]") {
    Parser p("info", "", "Description.");
    p.threads();
    CHECK(parse(p, {"--threads", "3"}).empty());
    CHECK(kappa::thread_count() == 3);
    CHECK(parse(p, {"--threads", "0"}).empty());  // back to the default
    CHECK(parse(p, {"--threads", "-2"}).find("--threads expects") != std::string::npos);
    kappa::set_thread_count(0);

    std::ostringstream captured;
    auto* old = std::cout.rdbuf(captured.rdbuf());
    Args args({"info", "--help", "--bogus"});
    const bool run = p.parse_or_throw(args.argc(), args.data());
    std::cout.rdbuf(old);
    CHECK_FALSE(run);
    CHECK(captured.str().rfind("Usage: kappa info", 0) == 0);
    CHECK(captured.str().find("--threads N") != std::string::npos);
}
