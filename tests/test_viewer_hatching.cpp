// Hatching in `kappa view` (Xvfb): while the view moves, and until the
// streamlines of the view at rest are traced on a worker thread, the frame
// is hatched by the GPU (--hatch-style shader); then the streamlines replace
// it. Each is compared with `kappa render` of the same saved view in that
// style: what the window shows is what the headless renderer draws.
#include <catch2/catch.hpp>

#include "test_support.h"

#include "render/image/image_writer.h"
#include "render/image/png_writer.h"

#include <cmath>
#include <string>

using namespace kappa;

namespace {

constexpr int kWidth = 480, kHeight = 400;

// Mean absolute difference per channel (0..255) of two images of one size.
double mean_difference(const render::Image& a, const render::Image& b) {
    double sum = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const auto p = a.at(x, y), q = b.at(x, y);
            sum += std::abs(p.r - q.r) + std::abs(p.g - q.g) + std::abs(p.b - q.b);
        }
    return sum / (3.0 * a.width * a.height);
}

render::Image rendered(const std::string& dir, const std::string& name, const std::string& style) {
    const std::string out = dir + "/" + name + "-rendered.png";
    const auto r = test::run_command(std::string(KAPPA_EXE) + " render -q -o " + out + " --xf " + dir +
                                     "/rest.xf --size " + std::to_string(kWidth) + "x" + std::to_string(kHeight) +
                                     " --detail off --lines none --hatching cross --hatch-style " + style);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return render::read_png(out);
}

}  // namespace

TEST_CASE("the viewer hatches with the shader while the view moves and with streamlines at rest", "[viewer][hatching]") {
    const std::string dir = test::temp_dir();
    // Detail off: the fields stay those of the mesh, so no recomputation follows the drag.
    test::write_file(dir + "/steps.txt",
                     "panel off\n"
                     "set detail off\n"
                     "set lines none\n"
                     "set hatching cross\n"
                     "frames 2\n"
                     "drag 240 200 262 192 left 4\n"
                     "screenshot " + dir + "/moved.png\n"
                     "wait-hatching\n"
                     "frames 1\n"
                     "screenshot " + dir + "/rest.png\n"
                     "save-view " + dir + "/rest.xf\n");
    const auto run = test::run_under_xvfb(std::string(KAPPA_EXE) + " view --size " + std::to_string(kWidth) + "x" +
                                          std::to_string(kHeight) + " --script " + dir + "/steps.txt");
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    const render::Image moved = render::read_png(dir + "/moved.png"), rest = render::read_png(dir + "/rest.png");
    const render::Image shader = rendered(dir, "shader", "shader"), streamlines = rendered(dir, "streamlines", "streamlines");
    REQUIRE(moved.width == shader.width);
    REQUIRE(moved.height == shader.height);
    // The frame right after the drag: the shader's strokes of that view.
    CHECK(mean_difference(moved, shader) < 1.0);
    // At rest: the streamlines of that view, as kappa render draws them.
    CHECK(mean_difference(rest, streamlines) < 1.0);
    // And the two styles differ (the test compares something).
    CHECK(mean_difference(shader, streamlines) > 3.0);
}
