// `kappa view` in a real window under Xvfb (xvfb-run -a), driven by a
// --script: the panel is drawn, the model is in the drawing area, an orbit
// changes the image, toggling contours off removes the line pixels, and a
// saved .xf view renders the same with `kappa render --xf`. Also the
// one-line error without a display. The keys: test_viewer_keys.cpp.
#include <catch2/catch.hpp>

#include "test_support.h"

#include "render/fields/field_upload.h"
#include "render/image/image.h"
#include "render/image/png_writer.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

using namespace kappa;

namespace {

// Window 800x500; the panel is 330 wide, so the drawing area is 470x500.
constexpr int kWidth = 800, kHeight = 500, kPanel = 330;

test::CommandResult run_viewer(const std::string& args) {
    return test::run_under_xvfb(std::string(KAPPA_EXE) + " view " + args);
}

bool is_dark(const render::Rgba& p) { return p.r < 90 && p.g < 90 && p.b < 90; }
// ImGui's accent blue (headers, check marks, slider grabs) over its dark panel.
bool is_panel_blue(const render::Rgba& p) { return p.b > p.r + 40 && p.b > 70; }

size_t count(const render::Image& im, int x0, int y0, int x1, int y1, bool (*pred)(const render::Rgba&)) {
    size_t n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) n += pred(im.at(x, y));
    return n;
}

// Mean absolute difference per channel (0..255) over a region of two images.
double mean_difference(const render::Image& a, int ax, const render::Image& b, int bx, int w, int h) {
    double sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto p = a.at(ax + x, y), q = b.at(bx + x, y);
            sum += std::abs(p.r - q.r) + std::abs(p.g - q.g) + std::abs(p.b - q.b);
        }
    return sum / (3.0 * w * h);
}

// One scripted run shared by the test cases (llvmpipe on 2 cores: keep it to one).
struct ScriptedRun {
    std::string dir;
    test::CommandResult result;
    ScriptedRun() : dir(test::temp_dir()) {
        test::write_file(dir + "/steps.txt",
                         "frames 2\n"
                         "screenshot " + dir + "/start.png\n"
                         "screenshot " + dir + "/start-drawing.png no-panel\n"
                         "drag 565 250 700 230 left 6\n"
                         "frames 1\n"
                         "wait-compute\n"
                         "frames 1\n"
                         "screenshot " + dir + "/orbited.png no-panel\n"
                         "save-view " + dir + "/orbited.xf\n"

                         "set shading none\n"
                         "set lines contours\n"
                         "frames 1\n"
                         "screenshot " + dir + "/contours.png no-panel\n"
                         "key C\n"
                         "frames 1\n"
                         "screenshot " + dir + "/no-lines.png no-panel\n"
                         "key C\n"
                         "screenshot " + dir + "/window-lines.png\n"
                         "set shading lambert\n"
                         "set lines contours,suggestive\n"
                         "scroll 565 250 4\n"
                         "wait-compute\n"
                         "frames 1\n"
                         "screenshot " + dir + "/zoomed.png no-panel\n"
                         "save-view " + dir + "/zoomed.xf\n"
                         "set detail off\n"
                         "wait-compute\n"
                         "frames 1\n"
                         "screenshot " + dir + "/raw.png no-panel\n"
                         "save-view " + dir + "/raw.xf\n");
        result = run_viewer("--size " + std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --script " +
                            dir + "/steps.txt");
    }
    render::Image image(const std::string& name) const { return render::read_png(dir + "/" + name); }
};

const ScriptedRun& scripted_run() {
    static const ScriptedRun run;
    return run;
}

}  // namespace

TEST_CASE("without a display, kappa view says to use kappa render in one line", "[viewer][window]") {
    const auto r = test::run_command("env -u DISPLAY " + std::string(KAPPA_EXE) + " view");
    CHECK(r.exit_code == 1);
    CHECK(r.output.find("no display") != std::string::npos);
    CHECK(r.output.find("kappa render") != std::string::npos);
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
    // A display that cannot be opened: the same kind of message.
    const auto bad = test::run_command("DISPLAY=:4242 " + std::string(KAPPA_EXE) + " view");
    CHECK(bad.exit_code == 1);
    CHECK(bad.output.find("kappa render") != std::string::npos);
}

TEST_CASE("kappa view --frames N --screenshot saves the whole window: panel at the left, model in the drawing area",
          "[viewer][window]") {
    const std::string dir = test::temp_dir();
    const auto r = run_viewer("--size 800x500 --frames 2 --screenshot " + dir + "/shot.png");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("first frame at") != std::string::npos);
    const render::Image im = render::read_png(dir + "/shot.png");
    REQUIRE(im.width == kWidth);
    REQUIRE(im.height == kHeight);
    // The panel: mostly dark, with ImGui's accent blue in its headers and check boxes.
    const size_t panel_px = size_t(kPanel - 20) * 300;
    CHECK(count(im, 10, 0, kPanel - 10, 300, is_dark) > panel_px / 2);
    CHECK(count(im, 10, 0, kPanel - 10, 300, is_panel_blue) > 1000);
    // The model: shaded (grey, not the white background) at the drawing area's centre,
    // white background near its corners.
    const int cx = kPanel + (kWidth - kPanel) / 2, cy = kHeight / 2;
    const auto centre = im.at(cx, cy);
    CHECK(centre.r < 250);
    CHECK(centre.r > 60);
    CHECK(im.at(kWidth - 3, 3).r == 255);
    CHECK(count(im, kPanel, 0, kWidth, kHeight, is_panel_blue) == 0);
}

TEST_CASE("a scripted orbit changes the drawing", "[viewer][window]") {
    const ScriptedRun& run = scripted_run();
    INFO(run.result.output);
    REQUIRE(run.result.exit_code == 0);
    const render::Image before = run.image("start-drawing.png"), after = run.image("orbited.png");
    REQUIRE(before.width == kWidth - kPanel);
    REQUIRE(after.width == before.width);
    CHECK(mean_difference(before, 0, after, 0, before.width, before.height) > 3.0);
}

TEST_CASE("the drawing without the panel is the window's drawing area", "[viewer][window]") {
    const ScriptedRun& run = scripted_run();
    INFO(run.result.output);
    REQUIRE(run.result.exit_code == 0);
    const render::Image window = run.image("start.png"), drawing = run.image("start-drawing.png");
    CHECK(mean_difference(window, kPanel, drawing, 0, drawing.width, drawing.height) < 1.0);
}

TEST_CASE("toggling contours off with the C key removes the line pixels", "[viewer][window]") {
    const ScriptedRun& run = scripted_run();
    INFO(run.result.output);
    REQUIRE(run.result.exit_code == 0);
    // --shading none: a white surface, so dark pixels are lines.
    const render::Image lines = run.image("contours.png"), none = run.image("no-lines.png");
    const size_t with = count(lines, 0, 0, lines.width, lines.height, is_dark);
    const size_t without = count(none, 0, 0, none.width, none.height, is_dark);
    CHECK(with > 500);  // the silhouette, ~2 px wide
    CHECK(without < with / 50);
    // Pressing C again brings them back (the whole window this time, panel included).
    const render::Image back = run.image("window-lines.png");
    CHECK(count(back, kPanel, 0, kWidth, kHeight, is_dark) > with * 9 / 10);
}

TEST_CASE("a view saved as .xf renders the same with kappa render --xf", "[viewer][window][xf]") {
    const ScriptedRun& run = scripted_run();
    INFO(run.result.output);
    REQUIRE(run.result.exit_code == 0);
    // The orbited view, and a zoomed one: the viewer's detail fields follow
    // the view (computed on its worker) as kappa render's do.
    // `set detail off` then draws the raw 1-ring lines, as --detail off does.
    for (const std::string view : {"orbited", "zoomed", "raw"}) {
        const std::string out = run.dir + "/rendered-" + view + ".png";
        const auto r = test::run_command(std::string(KAPPA_EXE) + " render -q -o " + out + " --xf " + run.dir +
                                         "/" + view + ".xf --size " + std::to_string(kWidth - kPanel) + "x" +
                                         std::to_string(kHeight) + (view == "raw" ? " --detail off" : ""));
        INFO(view << ": " << r.output);
        REQUIRE(r.exit_code == 0);
        const render::Image viewer = run.image(view + ".png"), headless = render::read_png(out);
        REQUIRE(headless.width == viewer.width);
        REQUIRE(headless.height == viewer.height);
        CHECK(mean_difference(viewer, 0, headless, 0, viewer.width, viewer.height) < 1.0);
    }
    // The orbit's and the zoom's fields were sent to the GPU (in slices, MeshBuffers::begin_upload)
    // before their screenshots: wait-compute waits for the last slice.
    const size_t landed = run.result.output.find("new fields landed ");
    REQUIRE(landed != std::string::npos);
    CHECK(std::atoi(run.result.output.c_str() + landed + std::strlen("new fields landed ")) >= 2);
    // Zooming changed the picture (not the same image twice).
    CHECK(mean_difference(run.image("orbited.png"), 0, run.image("zoomed.png"), 0, kWidth - kPanel, kHeight) > 5.0);
    CHECK(mean_difference(run.image("zoomed.png"), 0, run.image("raw.png"), 0, kWidth - kPanel, kHeight) > 0.05);
}

// A big mesh's first view (1M faces and more) gets its detail fields from
// the worker, as later views do: made on the window's thread they froze it
// (about a second for bunny-1M here, 20 s for 17.8M faces). The window goes on
// drawing frames meanwhile (with the progress bar), sends the view to the GPU
// in 8 MiB slices, and then draws what kappa render draws for the same view.
TEST_CASE("a big mesh's first view is made on the worker while the window draws, then is kappa render's",
          "[viewer][window][xf]") {
    const std::string dir = test::temp_dir();
    test::write_file(dir + "/steps.txt", "frames 1\n"
                                         "wait-compute\n"
                                         "frames 1\n"
                                         "screenshot " + dir + "/first.png no-panel\n"
                                         "save-view " + dir + "/first.xf\n");
    const auto r = run_viewer(test::shared_mesh("bunny-1M.ply") + " --size " + std::to_string(kWidth) + "x" +
                              std::to_string(kHeight) + " --script " + dir + "/steps.txt");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    // "...; first frame at T s (load ..., upload ...; N frames drawn while the worker made its fields)"
    const size_t while_made = r.output.find(" frames drawn while the worker made its fields");
    REQUIRE(while_made != std::string::npos);
    const size_t number = r.output.rfind("; ", while_made) + 2;
    CHECK(std::atoi(r.output.c_str() + number) >= 1);
    // "PATH: V vertices, F faces; ... , M while it was sent to the GPU in S slices": S is the
    // triangles, vertex records and positions in 8 MiB slices, and one more making the spare
    // buffers later views go to.
    const size_t counts = r.output.find("bunny-1M.ply: ");
    REQUIRE(counts != std::string::npos);
    const size_t vertices = std::strtoull(r.output.c_str() + counts + 14, nullptr, 10);
    const size_t faces = std::strtoull(r.output.c_str() + r.output.find(" vertices, ", counts) + 11, nullptr, 10);
    const size_t sent = r.output.find(" while it was sent to the GPU in ");
    REQUIRE(sent != std::string::npos);
    const size_t bytes = faces * 3 * sizeof(uint32_t) + vertices * (sizeof(render::GpuVertex) + 3 * sizeof(float));
    CHECK(std::strtoull(r.output.c_str() + sent + 33, nullptr, 10) ==
          (bytes + (size_t(8) << 20) - 1) / (size_t(8) << 20) + 1);
    CHECK(vertices > 500000);
    const std::string out = dir + "/rendered.png";
    const auto rendered = test::run_command(std::string(KAPPA_EXE) + " render " + test::shared_mesh("bunny-1M.ply") +
                                            " -q -o " + out + " --xf " + dir + "/first.xf --size " +
                                            std::to_string(kWidth - kPanel) + "x" + std::to_string(kHeight));
    INFO(rendered.output);
    REQUIRE(rendered.exit_code == 0);
    const render::Image viewer = render::read_png(dir + "/first.png"), headless = render::read_png(out);
    REQUIRE(headless.width == viewer.width);
    REQUIRE(headless.height == viewer.height);
    CHECK(count(viewer, 0, 0, viewer.width, viewer.height, is_dark) > 500);  // lines drawn
    CHECK(mean_difference(viewer, 0, headless, 0, viewer.width, viewer.height) < 1.0);
}

TEST_CASE("script errors name the file and line and the viewer exits 1", "[viewer][window]") {
    const std::string dir = test::temp_dir();
    test::write_file(dir + "/bad.txt", "frames 1\n\ndrag 1 2 three 4\n");
    const auto r = test::run_command(std::string(KAPPA_EXE) + " view --script " + dir + "/bad.txt");
    CHECK(r.exit_code == 1);
    CHECK(r.output.find(dir + "/bad.txt:3:") != std::string::npos);
    CHECK(r.output.find("'three' is not a number") != std::string::npos);
    test::write_file(dir + "/bad2.txt", "set shading glossy\n");
    const auto r2 = test::run_command(std::string(KAPPA_EXE) + " view --script " + dir + "/bad2.txt");
    CHECK(r2.exit_code == 1);
    CHECK(r2.output.find("bad2.txt:1: --shading expects one of none, lambert, toon, hemisphere, toon-bw, gooch, got 'glossy'") !=
          std::string::npos);
}

TEST_CASE("a mesh that cannot be read ends a scripted run with one line naming it", "[viewer][window]") {
    const std::string dir = test::temp_dir();
    test::write_file(dir + "/broken.ply", "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2\n");
    const auto r = run_viewer(dir + "/broken.ply --size 320x240 --frames 1");
    INFO(r.output);
    CHECK(r.exit_code == 1);
    CHECK(r.output.find("kappa view: " + dir + "/broken.ply") != std::string::npos);
    CHECK(test::count_lines(r.output) == 1);
}
