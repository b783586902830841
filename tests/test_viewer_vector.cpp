// The viewer saves its current view as SVG or PDF (a screenshot path ending
// in .svg or .pdf): strokes of exactly the fields drawn, matching the
// viewer's own PNG of the drawing area.
#include <catch2/catch.hpp>

#include "test_support.h"

#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"

#include <string>

using namespace kappa;

TEST_CASE("kappa view saves the drawing area as SVG that matches its PNG", "[viewer][vector]") {
    const std::string dir = test::temp_dir();
    test::write_file(dir + "/steps.txt",
                     "set shading none\n"
                     "frames 3\n"
                     "drag 200 200 260 230\n"
                     "frames 3\n"
                     "wait-compute\n"
                     "frames 2\n"
                     "screenshot " + dir + "/view.png no-panel\n"
                     "screenshot " + dir + "/view.svg\n"
                     "frames 1\n");
    const auto r = test::run_under_xvfb(std::string(KAPPA_EXE) + " view " + test::shared_mesh("bunny.ply") +
                                        " --size 800x500 --script " + dir + "/steps.txt");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    REQUIRE(test::run_command("rsvg-convert " + dir + "/view.svg -o " + dir + "/svg.png").exit_code == 0);
    const render::Image png = render::read_png(dir + "/view.png"), svg = render::read_png(dir + "/svg.png");
    REQUIRE(svg.width == png.width);
    REQUIRE(svg.height == png.height);
    CHECK(render::count_ink(png) > 1000);
    const double there = render::ink_within(svg, png, 2.0f), back = render::ink_within(png, svg, 2.0f);
    INFO("SVG ink near the PNG's: " << there << ", and back: " << back);
    CHECK(there >= 0.95);
    CHECK(back >= 0.95);
}
