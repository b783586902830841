// Line coverage drawn on the CPU (render/lines/line_raster.h) is lines_frag.glsl's:
// box-filtered coverage of a line of width w is clamp(w/2 + 1/2 - d, 0, 1)
// at distance d from the centre line, visibility is decided at the closest
// point of the centre line, hidden parts are dashed at 35% ink with
// --hidden-lines, and the exterior silhouette needs background on one side.
// On a real mesh it draws what the GL draws from the same segments' quads.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"
#include "test_support.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/parallel/parallel.h"
#include "geometry/surface_analysis.h"
#include "render/lines/line_raster.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

using namespace kappa;

namespace {

constexpr int kW = 64, kH = 48;

render::LineRasterParams params() {
    render::LineRasterParams p;
    p.width = kW, p.height = kH, p.line_width = 1.0f;
    p.depth_params = {-1.0202f, -2.0202f};  // a perspective projection with near 1, far 100
    return p;
}

render::WindowSegment segment(glm::vec2 a, glm::vec2 b, float depth = 0.5f) {
    render::WindowSegment s;
    s.a = {a, depth}, s.b = {b, depth};
    s.alpha = {1, 1};
    return s;
}

std::vector<uint8_t> draw(const std::vector<render::WindowSegment>& segments, const std::vector<float>& depth,
                          const render::LineRasterParams& p = params()) {
    std::vector<uint8_t> coverage;
    render::rasterize_lines(segments, depth, p, coverage);
    return coverage;
}

uint8_t at(const std::vector<uint8_t>& c, int x, int y) { return c[size_t(y) * kW + size_t(x)]; }

}  // namespace

TEST_CASE("CPU line raster: coverage of a 1 px line is 1 - distance", "[render][line-raster]") {
    const std::vector<float> empty(kW * kH, 1.0f);  // no surface
    // Centred on row 10's pixel centres: full ink there, none on rows 9 and 11 (distance 1).
    const auto on_centres = draw({segment({10.5f, 10.5f}, {40.5f, 10.5f})}, empty);
    for (int x = 12; x <= 38; ++x) {
        CHECK(at(on_centres, x, 10) == 255);
        CHECK(at(on_centres, x, 9) == 0);
        CHECK(at(on_centres, x, 11) == 0);
    }
    // Between rows 9 and 10: half ink on both (127.5 rounds to 128).
    const auto between = draw({segment({10.5f, 10.0f}, {40.5f, 10.0f})}, empty);
    for (int x = 12; x <= 38; ++x) {
        CHECK(std::abs(int(at(between, x, 9)) - 128) <= 1);
        CHECK(std::abs(int(at(between, x, 10)) - 128) <= 1);
    }
    // Round ends: half a pixel beyond the end point along the line, then nothing.
    CHECK(at(on_centres, 10, 10) == 255);
    CHECK(at(on_centres, 41, 10) == 0);
    // A diagonal: every pixel centre within the line's reach gets 1 - distance.
    const auto diagonal = draw({segment({5.0f, 5.0f}, {40.0f, 30.0f})}, empty);
    const glm::vec2 a(5, 5), d = glm::normalize(glm::vec2(35, 25));
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const glm::vec2 p(x + 0.5f, y + 0.5f);
            const float t = glm::clamp(glm::dot(p - a, d), 0.0f, glm::length(glm::vec2(35, 25)));
            const float want = glm::clamp(1.0f - glm::distance(p, a + t * d), 0.0f, 1.0f) * 255.0f;
            INFO("pixel " << x << ", " << y);
            CHECK(std::abs(float(at(diagonal, x, y)) - want) <= 1.0f);
        }
    // Opacity interpolated along the segment, and overlapping lines take the maximum.
    render::WindowSegment fading = segment({10.5f, 20.5f}, {50.5f, 20.5f});
    fading.alpha = {0.0f, 1.0f};
    const auto faded = draw({fading, segment({30.5f, 10.5f}, {30.5f, 30.5f})}, empty);
    CHECK(std::abs(int(at(faded, 20, 20)) - 64) <= 1);  // a quarter of the way
    CHECK(at(faded, 30, 20) == 255);                    // the crossing: max, not a sum
    CHECK(std::abs(int(at(faded, 40, 20)) - 191) <= 1);
}

TEST_CASE("CPU line raster: occlusion, hidden-line dashes, exterior silhouette, thread count", "[render][line-raster]") {
    // A surface covering the left half, at window depth 0.3, nearer than the lines at 0.5.
    std::vector<float> depth(kW * kH, 1.0f);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW / 2; ++x) depth[size_t(y) * kW + size_t(x)] = 0.3f;
    const auto line = segment({2.5f, 20.5f}, {61.5f, 20.5f});
    const auto hidden = draw({line}, depth);
    for (int x = 4; x < kW / 2 - 2; ++x) CHECK(at(hidden, x, 20) == 0);
    for (int x = kW / 2 + 2; x < 60; ++x) CHECK(at(hidden, x, 20) == 255);
    // In front of the surface: drawn everywhere.
    const auto in_front = draw({segment({2.5f, 20.5f}, {61.5f, 20.5f}, 0.2f)}, depth);
    for (int x = 4; x < 60; ++x) CHECK(at(in_front, x, 20) == 255);
    // --hidden-lines: dashes 6 px long every 10 px at 35% ink, measured from the first end.
    render::LineRasterParams dashed = params();
    dashed.hidden_lines = true;
    const auto dashes = draw({line}, depth, dashed);
    for (int x = 4; x < kW / 2 - 2; ++x) {
        const float along = float(x) + 0.5f - 2.5f;
        const float phase = std::fmod(along, 10.0f);
        if (phase < 5.9f) CHECK(std::abs(int(at(dashes, x, 20)) - 89) <= 1);  // 0.35 x 255
        if (phase > 6.1f) CHECK(at(dashes, x, 20) == 0);
    }
    // The exterior silhouette: drawn only where background lies 2.5 px to one side.
    render::WindowSegment edge = segment({10.5f, 5.5f}, {10.5f, 40.5f}, 0.2f);  // inside the surface
    edge.exterior_only = true;
    render::WindowSegment border = segment({32.5f, 5.5f}, {32.5f, 40.5f}, 0.2f);  // on its right border
    border.exterior_only = true;
    const auto silhouette = draw({edge, border}, depth);
    for (int y = 8; y < 38; ++y) {
        CHECK(at(silhouette, 10, y) == 0);
        CHECK(at(silhouette, 32, y) == 255);
    }
    // The same bytes for one thread and many (each band of rows is its own).
    std::vector<render::WindowSegment> many;
    for (int i = 0; i < 400; ++i)
        many.push_back(segment({float(i % 61) + 0.3f, float(i % 47) * 0.9f}, {float((i * 7) % 63), float((i * 13) % 45)},
                               0.2f + 0.001f * float(i)));
    const unsigned threads = thread_count();
    set_thread_count(1);
    const auto one = draw(many, depth);
    set_thread_count(4);
    const auto four = draw(many, depth);
    set_thread_count(threads);
    CHECK(one == four);
}

TEST_CASE("CPU line raster draws what the GL draws from the same segments", "[render][line-raster]") {
    const Mesh mesh = load_mesh(test::shared_mesh("bunny.ply"));
    const SurfaceFields fields = compute_surface_fields(mesh);
    const float fs = feature_size(mesh, fields);
    const auto camera = render::Camera::default_view(mesh, render::bounding_sphere(mesh), 30.0f, 4.0f / 3.0f);
    render::LineSelection every{true, true, false, false};
    every.suggestive_highlights = every.dwkr = every.ridges = every.valleys = every.parabolic = every.mean_zero = true;
    every.apparent_ridges = every.principal_highlights = every.isophotes = every.topo = true;
    const bool default_raster = test::renderer().cpu_line_raster();
    for (bool hidden_lines : {false, true}) {
        INFO("hidden lines " << hidden_lines);
        render::RenderSettings s = test::lines_only(every);
        s.line_extraction = render::LineExtraction::Cpu;
        s.hidden_lines = hidden_lines;
        test::renderer().set_cpu_line_raster(false);
        const render::Image gl = test::render(mesh, fields, fs, camera, s, 640, 480);
        test::renderer().set_cpu_line_raster(true);
        const render::Image cpu = test::render(mesh, fields, fs, camera, s, 640, 480);
        // The same float arithmetic per pixel: only rounding differs (a visibility
        // test or quad edge exactly on a boundary flips in a few pixels).
        size_t ink = test::count_ink(gl), differ = 0, off_by_rounding = 0;
        for (size_t i = 0; i < gl.pixels.size(); ++i) {
            const int d = std::abs(int(gl.pixels[i]) - int(cpu.pixels[i]));
            differ += d > 2, off_by_rounding += d == 1 || d == 2;
        }
        INFO(ink << " ink pixels, " << differ << " channel values differ by more than 2, " << off_by_rounding
                 << " by 1 or 2");
        CHECK(ink > 5000);
        CHECK(double(differ) < 0.002 * double(ink));
    }
    test::renderer().set_cpu_line_raster(default_raster);
}

TEST_CASE("CPU line raster draws hatching strokes as the GL stroke pass does", "[render][line-raster][hatching]") {
    const Mesh mesh = load_mesh(test::shared_mesh("bunny.ply"));
    const SurfaceFields fields = compute_surface_fields(mesh);
    const float fs = feature_size(mesh, fields);
    const auto camera = render::Camera::default_view(mesh, render::bounding_sphere(mesh), 30.0f, 4.0f / 3.0f);
    const bool default_raster = test::renderer().cpu_line_raster();
    // Strokes alone, and with contours (one raster for both).
    for (const render::LineSelection lines :
         {render::LineSelection{false, false, false, false}, render::LineSelection{true, false, false, false}}) {
        render::RenderSettings s = test::lines_only(lines);
        s.line_extraction = render::LineExtraction::Cpu;
        s.hatching = render::Hatching::Cross;
        test::renderer().set_cpu_line_raster(false);
        const render::Image gl = test::render(mesh, fields, fs, camera, s, 640, 480);
        test::renderer().set_cpu_line_raster(true);
        const render::Image cpu = test::render(mesh, fields, fs, camera, s, 640, 480);
        test::maybe_save(cpu, "hatching_cpu_raster");
        size_t ink = test::count_ink(gl), differ = 0;
        for (size_t i = 0; i < gl.pixels.size(); ++i) differ += std::abs(int(gl.pixels[i]) - int(cpu.pixels[i])) > 2;
        INFO(render::to_string(lines) << ": " << ink << " ink pixels, " << differ << " channel values differ by more than 2");
        CHECK(ink > 5000);
        // As above: the same arithmetic, rounding apart; strokes stop at the
        // model's outline on both (drawn only over the surface).
        CHECK(double(differ) < 0.002 * double(ink));
    }
    test::renderer().set_cpu_line_raster(default_raster);
}

TEST_CASE("CPU line raster: non-finite and far-off segments draw nothing and stop", "[render][line-raster]") {
    const std::vector<float> empty(kW * kH, 1.0f);
    const float nan = std::nanf(""), inf = INFINITY;
    std::vector<render::WindowSegment> bad = {segment({nan, 10}, {20, 10}), segment({10, 10}, {inf, 10}),
                                              segment({10, nan}, {20, 30}), segment({-1e30f, 5}, {-1e29f, 40}),
                                              segment({5, 1e30f}, {6, 2e30f})};
    bad[0].alpha = {nan, 1};
    const auto coverage = draw(bad, empty);
    CHECK(std::count(coverage.begin(), coverage.end(), uint8_t(0)) == long(coverage.size()));
    // A vertical line's end rows cover only its end discs.
    const auto vertical = draw({segment({40.5f, 10.5f}, {40.5f, 30.5f})}, empty);
    for (int x = 0; x < kW; ++x) {
        if (x == 40) continue;
        CHECK(at(vertical, x, 10) == 0);
        CHECK(at(vertical, x, 30) == 0);
    }
    CHECK(at(vertical, 40, 10) == 255);
    CHECK(at(vertical, 40, 30) == 255);
}

TEST_CASE("Inked rectangles hold every inked pixel and little else", "[render][line-raster]") {
    // A 203 x 101 image (not a multiple of the 16 px cells): a few pixels and
    // a diagonal line of ink, the last column and row included.
    const int w = 203, h = 101;
    std::vector<uint8_t> coverage(size_t(w) * size_t(h), 0);
    auto ink = [&](int x, int y) { coverage[size_t(y) * size_t(w) + size_t(x)] = 1; };
    ink(0, 0), ink(w - 1, h - 1), ink(100, 50), ink(17, 3);
    for (int i = 0; i < 90; ++i) ink(30 + i, 5 + i);
    const std::vector<glm::ivec4> rects = render::inked_rectangles(coverage, w, h);
    std::vector<int> covered(coverage.size(), 0);
    long area = 0;
    for (const glm::ivec4& r : rects) {
        REQUIRE(r.x >= 0);
        REQUIRE(r.y >= 0);
        REQUIRE(r.z > 0);
        REQUIRE(r.w > 0);
        REQUIRE(r.x + r.z <= w);
        REQUIRE(r.y + r.w <= h);
        area += long(r.z) * r.w;
        for (int y = r.y; y < r.y + r.w; ++y)
            for (int x = r.x; x < r.x + r.z; ++x) ++covered[size_t(y) * size_t(w) + size_t(x)];
    }
    size_t outside = 0, twice = 0;
    for (size_t i = 0; i < coverage.size(); ++i) {
        outside += coverage[i] && covered[i] == 0;
        twice += covered[i] > 1;
    }
    CHECK(outside == 0);
    CHECK(twice == 0);  // each pixel blended once
    // The diagonal crosses at most 2 cells a cell row (7 rows), each lone pixel one cell.
    CHECK(area <= (2 * 7 + 4) * 16 * 16);
    CHECK(render::inked_rectangles(std::vector<uint8_t>(coverage.size(), 0), w, h).empty());
}
