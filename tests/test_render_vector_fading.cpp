// A fading stroke in SVG and PDF (render/vector/vector_drawing.h: pieces of one
// opacity each) read back by rsvg-convert and pdftoppm: along it, no pixel
// is inked more than the piece over it. Round caps overlapping at the
// joints of translucent pieces inked about 2a - a^2 there (beads).
#include <catch2/catch.hpp>

#include "test_support.h"

#include "render/image/png_writer.h"
#include "render/vector/vector_drawing.h"

#include <algorithm>
#include <string>

using namespace kappa;

TEST_CASE("a fading stroke in SVG and PDF has no darker beads where its pieces meet", "[render][vector]") {
    render::VectorDrawing d;
    d.width = 240, d.height = 40, d.line_width = 6;
    render::Stroke s;
    s.type = LineType::Suggestive;
    // Left to right, opacity from 0.2 to 0.8: pieces of 1/16 steps, about ten joints.
    for (int i = 0; i <= 100; ++i) {
        s.points.push_back({20.0f + 2.0f * float(i), 20.0f});
        s.opacity.push_back(0.2f + 0.006f * float(i));
    }
    d.strokes.push_back(s);
    REQUIRE(render::stroke_pieces(s, d).size() >= 8);
    const std::string dir = test::temp_dir();
    render::write_svg(dir + "/fade.svg", d);
    render::write_pdf(dir + "/fade.pdf", d);
    REQUIRE(test::run_command("rsvg-convert " + dir + "/fade.svg -o " + dir + "/svg.png").exit_code == 0);
    REQUIRE(test::run_command("pdftoppm -png -r 72 -singlefile " + dir + "/fade.pdf " + dir + "/pdf").exit_code == 0);
    for (const std::string name : {"svg", "pdf"}) {
        const render::Image im = render::read_png(dir + "/" + name + ".png");
        INFO(name);
        REQUIRE(im.width == d.width);
        float worst = 0, darkest = 0;
        for (int x = 24; x < 216; ++x) {
            const float ink = 1.0f - float(im.at(x, 20).r) / 255.0f;
            // The opacity of the piece over x, at most a 1/16 step above the linear ramp, and 1/64 of rasterising.
            const float allowed = 0.2f + 0.006f * float(x - 20) / 2.0f + 1.0f / 16.0f + 1.0f / 64.0f;
            worst = std::max(worst, ink - allowed);
            darkest = std::max(darkest, ink);
        }
        CHECK(darkest > 0.7f);  // the stroke is there, dark at its right end
        CHECK(worst <= 0.0f);
    }
}
