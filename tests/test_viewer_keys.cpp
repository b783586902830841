// The viewer's keys and script steps against `kappa render`: one scripted run
// of `kappa view` under Xvfb presses every key of app/viewer/shortcuts.cpp
// (and uses open, load-view, panel on, a pan and set estimator), and each
// drawing is compared with `kappa render` (through one `kappa batch`: one
// process, one GL context) with the options the key should have set, of the
// view the viewer saved. Every reference must also differ from the drawing
// before the key, so a key that does nothing, or the wrong thing, fails.
#include <catch2/catch.hpp>

#include "test_shapes.h"
#include "test_support.h"

#include "geometry/mesh/default_model.h"
#include "geometry/mesh/primitives.h"
#include "render/camera/camera.h"
#include "render/image/image.h"
#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace kappa;
namespace fs = std::filesystem;

namespace {

// The window; the panel, when shown, is at the left, 330 pixels wide but at
// most half the window (app/viewer/viewer_app.cpp's drawing_area).
constexpr int kWidth = 560, kHeight = 320, kPanel = 330 < kWidth / 2 ? 330 : kWidth / 2;

// Fraction of pixels whose colours differ by more than `tolerance` in some channel.
double differing(const render::Image& a, const render::Image& b, int tolerance = 40) {
    if (a.width != b.width || a.height != b.height) return 1.0;
    size_t n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const auto p = a.at(x, y), q = b.at(x, y);
            n += std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)}) > tolerance;
        }
    return double(n) / (double(a.width) * a.height);
}

bool is_dark(const render::Rgba& p) { return p.r < 90 && p.g < 90 && p.b < 90; }
bool is_panel_blue(const render::Rgba& p) { return p.b > p.r + 40 && p.b > 70; }
size_t count(const render::Image& im, int x0, int x1, bool (*pred)(const render::Rgba&)) {
    size_t n = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = x0; x < x1; ++x) n += pred(im.at(x, y));
    return n;
}

// Line-kind keys (item 7 of issue 29): key, kind.
const std::vector<std::pair<std::string, std::string>> kLineKeys = {
    {"C", "contours"},
    {"E", "silhouette"},
    {"S", "suggestive"},
    {"Ctrl+F", "suggestive-highlights"},
    {"W", "dwkr"},
    {"Ctrl+R", "ridges"},
    {"Ctrl+V", "valleys"},
    {"Ctrl+A", "apparent-ridges"},
    {"Ctrl+P", "principal-highlights"},
    {"Ctrl+K", "parabolic"},
    {"Ctrl+H", "mean-zero"},
    {"I", "isophotes"},
    {"T", "topo"},
};

// Setting keys: name of the screenshot, the script's steps, the options of
// `kappa render` that should give the same drawing, and the screenshot (or
// reference) it must differ from.
struct SettingKey {
    std::string name, steps, options, differs_from;
};
const std::string kLines = " --lines contours,suggestive --rv-threshold 0.2";
const std::vector<SettingKey> kSettingKeys = {
    {"base-none", "set lines contours,suggestive\n", " --shading none" + kLines, ""},
    {"L", "key L\n", " --shading lambert" + kLines, "base-none"},
    {"L2", "key L\n", " --shading toon" + kLines, "L"},
    {"lambert", "set shading lambert\n", " --shading lambert" + kLines, "L2"},
    {"Ctrl+L", "key Ctrl+L\n", " --shading lambert --light-frame model" + kLines, "lambert"},
    {"M", "key Ctrl+L\nkey M\n", " --shading lambert --colormap k1" + kLines, "lambert"},
    {"K", "key K\n", " --shading lambert --colormap k1 --colorbar" + kLines, "M"},
    {"H", "key K\nset colormap none\nkey H\n", " --shading lambert --hatching min" + kLines, "lambert"},
    {"G", "set hatching none\nkey G\n", " --shading lambert --fade off" + kLines, "lambert"},
    // Multisampling shows on the shaded surface's outline, where no line covers it.
    {"no-lines", "key G\nset lines none\n", " --shading lambert --lines none", ""},
    {"A", "key A\n", " --shading lambert --msaa off --lines none", "no-lines"},
    {"=", "key A\nset lines contours,suggestive\nkey =\n", " --shading lambert --line-width 2.5" + kLines, "lambert"},
    {"-", "key -\n", " --shading lambert" + kLines, "="},
    // Each ] multiplies the threshold by 1.5, each [ divides it by 1.5.
    {"]", "key ]\nkey ]\nkey ]\nkey ]\n", " --shading lambert --sc-threshold 0.253125" + kLines, "lambert"},
    {"[", "key [\nkey [\nkey [\nkey [\n", " --shading lambert" + kLines, "]"},
    {"D", "key D\n", " --shading lambert --hidden-lines on" + kLines, "lambert"},
};

std::string file_name(const std::string& key) {
    std::string s;
    for (char c : key) s += std::isalnum(static_cast<unsigned char>(c)) ? std::string(1, c) : "_" + std::to_string(int(c));
    return s;
}

// One scripted run, shared by the test cases (llvmpipe on 2 cores).
struct KeysRun {
    std::string dir;
    test::CommandResult result, batch;
    KeysRun() : dir(test::temp_dir()) {
        fs::create_directories(dir + "/cwd");
        test::write_off(dir + "/torus.off", make_torus(1.0f, 0.45f, 48, 24));
        std::string s = "panel off\nset shading none\nset lines none\nset rv-threshold 0.2\nframes 2\n"
                        "save-view " + dir + "/start.xf\n"
                        "screenshot " + dir + "/none.png no-panel\n";
        for (const auto& [key, kind] : kLineKeys)
            s += "key " + key + "\nframes 1\nscreenshot " + dir + "/kind-" + kind + ".png no-panel\nkey " + key + "\n";
        s += "frames 1\nscreenshot " + dir + "/none-again.png no-panel\n";
        for (const SettingKey& k : kSettingKeys)
            s += k.steps + "frames 1\nscreenshot " + dir + "/key-" + file_name(k.name) + ".png no-panel\n";
        s += "key D\n"
             // Views: pan (right drag), zoom and F: the start view again.
             "drag 280 160 320 185 right 4\nframes 1\n"
             "screenshot " + dir + "/panned.png no-panel\nsave-view " + dir + "/panned.xf\n"
             "scroll 280 160 3\nkey F\nframes 1\nscreenshot " + dir + "/fit.png no-panel\n"
             // Orbit, then F keeps the orientation; R goes back to the start.
             "drag 280 160 340 140 left 4\nframes 1\nsave-view " + dir + "/orbited.xf\n"
             "scroll 280 160 2\nkey F\nframes 1\nsave-view " + dir + "/orbit-fit.xf\n"
             "key R\nframes 1\nscreenshot " + dir + "/reset.png no-panel\nsave-view " + dir + "/reset.xf\n"
             // Ctrl+S saves the view to kappa-view.xf (in the working folder); Ctrl+O reads it back.
             "key Ctrl+S\ndrag 280 160 200 160 left 4\nframes 1\nkey Ctrl+O\nframes 1\n"
             "screenshot " + dir + "/loaded.png no-panel\n"
             // load-view of another view.
             "load-view " + dir + "/panned.xf\nframes 1\nscreenshot " + dir + "/load-view.png no-panel\n"
             "load-view " + dir + "/start.xf\n"
             // P: kappa-view.png of the whole window; Tab and panel on show the panel.
             "key P\nframes 2\nscreenshot " + dir + "/window.png\n"
             "key Tab\nframes 2\nscreenshot " + dir + "/tab-on.png\nscreenshot " + dir + "/tab-on-drawing.png no-panel\n"
             "key Tab\nframes 2\nscreenshot " + dir + "/tab-off.png\nscreenshot " + dir + "/tab-off-drawing.png no-panel\n"
             "panel on\nframes 2\nscreenshot " + dir + "/panel-on.png\nscreenshot " + dir + "/panel-on-drawing.png no-panel\n"
             "panel off\n"
             // set estimator: the colour map of jet's fields.
             "set colormap k1\nset estimator jet\nwait-compute\nframes 1\n"
             "screenshot " + dir + "/jet.png no-panel\n"
             // open: another mesh, drawn with the settings in force.
             "open " + dir + "/torus.off\nwait-compute\nframes 1\n"
             "screenshot " + dir + "/opened.png no-panel\nsave-view " + dir + "/opened.xf\n";
        test::write_file(dir + "/steps.txt", s);
        result = test::run_under_xvfb("sh -c 'cd " + dir + "/cwd && exec " + std::string(KAPPA_EXE) + " view --no-panel --size " +
                                      std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --script " + dir +
                                      "/steps.txt'");
        // The references, one batch.
        const std::string size = " --size " + std::to_string(kWidth) + "x" + std::to_string(kHeight);
        const std::string start = size + " --xf " + dir + "/start.xf";
        std::string jobs = "- ref-none.png" + start + " --shading none --lines none\n";
        for (const auto& [key, kind] : kLineKeys)
            jobs += "- ref-kind-" + kind + ".png" + start + " --shading none --lines " + kind + " --rv-threshold 0.2\n";
        for (const SettingKey& k : kSettingKeys) jobs += "- ref-key-" + file_name(k.name) + ".png" + start + k.options + "\n";
        const std::string lambert = " --shading lambert" + kLines;
        jobs += "- ref-panned.png" + size + " --xf " + dir + "/panned.xf" + lambert + "\n";
        jobs += "- ref-jet.png" + start + lambert + " --colormap k1 --estimator jet\n";
        jobs += "torus.off ref-opened.png" + size + " --xf " + dir + "/opened.xf" + lambert +
                " --colormap k1 --estimator jet\n";
        test::write_file(dir + "/refs.txt", jobs);
        batch = test::run_command(std::string(KAPPA_EXE) + " batch -q " + dir + "/refs.txt");
    }
    render::Image image(const std::string& name) const { return render::read_png(dir + "/" + name); }
};

const KeysRun& keys_run() {
    static const KeysRun run;
    return run;
}

#define REQUIRE_RUN(run)                      \
    INFO((run).result.output << (run).batch.output); \
    REQUIRE((run).result.exit_code == 0);     \
    REQUIRE((run).batch.exit_code == 0)

}  // namespace

static void line_keys(const KeysRun& run) {
    const render::Image none = run.image("none.png");
    REQUIRE(none.width == kWidth);  // the panel is off: the whole window draws
    CHECK(differing(none, run.image("ref-none.png")) < 0.002);
    CHECK(differing(none, run.image("none-again.png")) == 0);  // each key again turned its kind off
    for (const auto& [key, kind] : kLineKeys) {
        const render::Image viewer = run.image("kind-" + kind + ".png"), reference = run.image("ref-kind-" + kind + ".png");
        const size_t ink = render::count_ink(reference);
        const double agree = std::min(render::ink_within(viewer, reference, 1.0f), render::ink_within(reference, viewer, 1.0f));
        INFO(key << " (" << kind << "): kappa render --lines " << kind << " has " << ink << " ink pixels; viewer "
                 << render::count_ink(viewer) << ", agreement within 1 px " << agree << ", pixels differing "
                 << differing(viewer, reference));
        CHECK(ink > 100);
        CHECK(agree > 0.98);
        CHECK(differing(viewer, reference) < 0.002);
    }
}

TEST_CASE("kappa view --help names each key with its own line kind and action", "[viewer][keys]") {
    const auto help = test::run_command(std::string(KAPPA_EXE) + " view --help");
    REQUIRE(help.exit_code == 0);
    // key -> words its help line must hold (and, for ridges, must not).
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"C", "occluding contours"}, {"E", "exterior silhouette"}, {"S", "suggestive contours"},
        {"Ctrl+F", "suggestive highlights"}, {"W", "Dw kr"}, {"B", "boundary"}, {"Ctrl+R", "ridges"},
        {"Ctrl+V", "valleys"}, {"Ctrl+A", "apparent ridges"}, {"Ctrl+P", "principal highlights"},
        {"Ctrl+K", "parabolic"}, {"Ctrl+H", "H = 0"}, {"I", "isophotes"}, {"T", "topographic"},
        {"D", "hidden lines"}, {"L", "shading"}, {"Ctrl+L", "light"}, {"M", "colour map"}, {"K", "colour bar"},
        {"H", "hatching"}, {"G", "fading"}, {"A", "multisampling"}, {"=", "wider"}, {"-", "thinner"},
        {"]", "raise"}, {"[", "lower"}, {"F", "fit"}, {"R", "reset"}, {"Tab", "panel"}, {"P", "screenshot"},
        {"Ctrl+S", "save the view"}, {"Ctrl+O", "load the view"},
    };
    std::vector<std::string> lines;
    std::istringstream in(help.output);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    for (const auto& [key, words] : expected) {
        INFO(key << ": " << words);
        std::string own;
        for (const auto& line : lines) {
            std::istringstream w(line);
            std::string first;
            if (line.rfind("  ", 0) == 0 && (w >> first) && first == key && own.empty()) own = line;
        }
        CHECK(own.find(words) != std::string::npos);
        if (key == "Ctrl+R") CHECK(own.find("apparent") == std::string::npos);
    }
}

static void setting_keys(const KeysRun& run) {
    for (const SettingKey& k : kSettingKeys) {
        const render::Image viewer = run.image("key-" + file_name(k.name) + ".png"),
                            reference = run.image("ref-key-" + file_name(k.name) + ".png");
        const double same = differing(viewer, reference, 8) * kWidth * kHeight;
        INFO(k.name << ": kappa render" << k.options << ": " << same << " pixels differ");
        CHECK(same <= 2);  // measured 0: the viewer's screenshot and kappa render draw alike
        if (!k.differs_from.empty()) {
            const double other =
                differing(reference, run.image("ref-key-" + file_name(k.differs_from) + ".png"), 8) * kWidth * kHeight;
            INFO("from " << k.differs_from << ": " << other << " pixels differ");
            CHECK(other >= 50);  // the key changed the drawing (measured 69 to 44390)
        }
    }
}

static void view_keys(const KeysRun& run) {
    const render::Image start = run.image("key-_91.png");  // lambert, the start view (after '[')
    // A right drag from (280, 160) to (320, 185) pans: the pivot, the
    // bounding sphere's centre at the middle of the window, is then under the
    // cursor; the drawing moves with it (nearer and farther parts by more and less).
    const render::BoundingSphere sphere = render::bounding_sphere(make_default_model());
    auto pixel_of = [&](const glm::mat4& view, glm::vec3 p) {
        const glm::vec3 c(view * glm::vec4(p, 1));
        const float t = std::tan(glm::radians(render::rtsc_fov_y_deg(kWidth, kHeight)) / 2);
        return glm::vec2(kWidth / 2.0f + c.x / -c.z / t * kHeight / 2.0f, kHeight / 2.0f - c.y / -c.z / t * kHeight / 2.0f);
    };
    const glm::mat4 s = render::read_xf(run.dir + "/start.xf"), pan = render::read_xf(run.dir + "/panned.xf");
    const glm::vec2 before = pixel_of(s, sphere.center), after = pixel_of(pan, sphere.center);
    INFO("centre at " << before.x << ", " << before.y << ", after the pan " << after.x << ", " << after.y);
    CHECK(glm::length(before - glm::vec2(280, 160)) < 0.1f);
    CHECK(glm::length(after - glm::vec2(320, 185)) < 0.1f);
    const render::Image panned = run.image("panned.png");
    auto ink_centre = [](const render::Image& im) {
        double sx = 0, sy = 0, n = 0;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x)
                if (render::is_ink(im.at(x, y))) sx += x, sy += y, n += 1;
        return glm::dvec2(sx / n, sy / n);
    };
    const glm::dvec2 moved = ink_centre(panned) - ink_centre(start);
    INFO("ink centre moved by " << moved.x << ", " << moved.y);
    CHECK(std::fabs(moved.x - 40) < 8);  // measured 38.1
    CHECK(std::fabs(moved.y - 25) < 6);  // measured 26.1
    CHECK(differing(panned, run.image("ref-panned.png")) < 0.002);
    // F after the pan and a zoom: the model fitted again, as at the start.
    CHECK(differing(run.image("fit.png"), start) < 0.002);
    // F after an orbit and a zoom keeps the orbit's orientation and puts the
    // bounding sphere's centre straight ahead at the start's distance.
    const glm::mat4 o = render::read_xf(run.dir + "/orbited.xf"), f = render::read_xf(run.dir + "/orbit-fit.xf");
    const glm::vec3 cs(s * glm::vec4(sphere.center, 1)), cf(f * glm::vec4(sphere.center, 1));
    INFO("centre in the start view " << cs.x << " " << cs.y << " " << cs.z << ", after orbit and F " << cf.x << " "
                                     << cf.y << " " << cf.z);
    CHECK(std::fabs(cs.x) < 1e-4f * sphere.radius);
    CHECK(std::fabs(cs.y) < 1e-4f * sphere.radius);
    CHECK(glm::length(cf - cs) < 1e-3f * sphere.radius);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) {
            CHECK(std::fabs(f[c][r] - o[c][r]) < 1e-4f);  // the orbited orientation, kept
        }
    CHECK(std::fabs(o[0][0] - s[0][0]) + std::fabs(o[2][0] - s[2][0]) > 0.05f);  // which differs from the start's
    // R: the start view again, image and matrix.
    CHECK(differing(run.image("reset.png"), start) < 0.002);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) CHECK(std::fabs(render::read_xf(run.dir + "/reset.xf")[c][r] - s[c][r]) < 1e-4f * (1 + std::fabs(s[c][r])));
    // Ctrl+S wrote the start view to kappa-view.xf in the working folder; Ctrl+O read it back after an orbit.
    REQUIRE(fs::exists(run.dir + "/cwd/kappa-view.xf"));
    const glm::mat4 saved = render::read_xf(run.dir + "/cwd/kappa-view.xf");
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) CHECK(std::fabs(saved[c][r] - s[c][r]) < 1e-4f * (1 + std::fabs(s[c][r])));
    CHECK(differing(run.image("loaded.png"), start) < 0.002);
    // load-view: the panned view's drawing.
    CHECK(differing(run.image("load-view.png"), panned) < 0.002);
}

static void window_keys_and_steps(const KeysRun& run) {
    // P: the whole window as kappa-view.png in the working folder.
    CHECK(fs::exists(run.dir + "/cwd/kappa-view.png"));
    if (fs::exists(run.dir + "/cwd/kappa-view.png")) {
        const render::Image p = render::read_png(run.dir + "/cwd/kappa-view.png"), window = run.image("window.png");
        CHECK(p.width == kWidth);
        CHECK(p.height == kHeight);
        CHECK(differing(p, window, 8) == 0);
    }
    // Tab and `panel on` show the panel at the left (dark, ImGui's blue), Tab again hides it.
    const size_t panel_px = size_t(kPanel - 20) * kHeight;
    for (const char* shown : {"tab-on.png", "panel-on.png"}) {
        const render::Image im = run.image(shown);
        INFO(shown);
        CHECK(count(im, 10, kPanel - 10, is_dark) > panel_px / 2);
        CHECK(count(im, 10, kPanel - 10, is_panel_blue) > 1000);
    }
    for (const char* hidden : {"window.png", "tab-off.png"}) {
        const render::Image im = run.image(hidden);
        INFO(hidden);
        CHECK(count(im, 10, kPanel - 10, is_panel_blue) == 0);
        CHECK(count(im, 10, kPanel - 10, is_dark) < panel_px / 10);
    }
    // The panel takes its width from the drawing area.
    for (const char* shown : {"tab-on-drawing.png", "panel-on-drawing.png"}) {
        INFO(shown);
        CHECK(run.image(shown).width == kWidth - kPanel);
    }
    CHECK(run.image("tab-off-drawing.png").width == kWidth);
    // set estimator jet: the colour map of jet's fields, not rusinkiewicz's.
    const render::Image jet = run.image("jet.png");
    CHECK(differing(jet, run.image("ref-jet.png")) < 0.002);
    CHECK(differing(run.image("ref-jet.png"), run.image("ref-key-M.png")) > 0.002);
    // open: the torus, drawn with the settings in force.
    const render::Image opened = run.image("opened.png");
    CHECK(differing(opened, run.image("ref-opened.png")) < 0.002);
    CHECK(differing(opened, jet) > 0.05);
}

TEST_CASE("the viewer's keys and script steps draw what kappa render draws with the same settings",
          "[viewer][window][keys]") {
    // One scripted run and one batch for all the sections (they are slow on llvmpipe).
    const KeysRun& run = keys_run();
    REQUIRE_RUN(run);
    SECTION("each line key draws its own kind: the drawing of kappa render --lines KIND") { line_keys(run); }
    SECTION("L, Ctrl+L, M, K, H, G, A, =, -, ], [ and D set what kappa render's options set") { setting_keys(run); }
    SECTION("pan, F, R, Ctrl+S, Ctrl+O and load-view move the camera as they should") { view_keys(run); }
    SECTION("P, Tab, panel on, set estimator and open") { window_keys_and_steps(run); }
}
