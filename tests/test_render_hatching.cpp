// Principal-direction hatching: strokes follow the chosen principal
// direction in the image, and there is more ink where the tone is darker.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"

#include "geometry/mesh/primitives.h"
#include "render/image/ink_agreement.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

using namespace kappa;

namespace {

constexpr int kSize = 512;

struct Window {
    double horizontal = 0;  // mean |I(x+1, y) - I(x, y)|: high across vertical strokes
    double vertical = 0;    // mean |I(x, y+1) - I(x, y)|: high across horizontal strokes
    double ink = 0;         // mean darkness in [0, 1]
};

Window measure(const render::Image& image, glm::vec2 center, int half) {
    Window w;
    int n = 0;
    auto lum = [&](int x, int y) { return image.at(x, y).g / 255.0; };
    for (int y = int(center.y) - half; y <= int(center.y) + half; ++y)
        for (int x = int(center.x) - half; x <= int(center.x) + half; ++x) {
            w.horizontal += std::abs(lum(x + 1, y) - lum(x, y));
            w.vertical += std::abs(lum(x, y + 1) - lum(x, y));
            w.ink += 1.0 - lum(x, y);
            ++n;
        }
    w.horizontal /= n, w.vertical /= n, w.ink /= n;
    return w;
}

}  // namespace

TEST_CASE("hatching strokes follow the principal directions, denser where darker", "[render][hatching]") {
    // Torus seen from straight above; at the front of the tube's top the
    // tube direction d1 (k1 = 1/r) runs up the image and the big circle
    // direction d2 across it. The light comes from the right. Both styles:
    // the streamlines and the shader's strokes (shaders/hatching/shader_hatching.glsl).
    const render::HatchStyle style = GENERATE(render::HatchStyle::Streamlines, render::HatchStyle::Shader);
    INFO("hatch style " << render::to_string(style));
    const Mesh torus = make_torus(1.0f, 0.4f, 160, 64);
    const SurfaceFields fields = test::torus_fields(torus, 1.0f, 0.4f);
    const auto camera = render::Camera::look_at({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40.0f);
    const auto bounds = render::bounding_sphere(torus);
    auto s = test::lines_only({false, false, false});
    s.light_dir = glm::normalize(glm::vec3(0.85f, 0, 0.53f));
    s.hatch_style = style;
    const glm::vec2 front_top = test::project(camera, bounds, {0, -1, 0.4f}, kSize, kSize);

    SECTION("max: strokes along d1, vertical here") {
        s.hatching = render::Hatching::Max;
        const auto image = test::render(torus, fields, 0.4f, camera, s, kSize, kSize);
        test::maybe_save(image, "torus_hatch_max_" + render::to_string(style));
        const Window w = measure(image, front_top, 12);
        INFO("horizontal variation " << w.horizontal << ", vertical " << w.vertical);
        CHECK(w.horizontal > 3 * w.vertical);
    }
    SECTION("min: strokes along d2, horizontal here") {
        s.hatching = render::Hatching::Min;
        const auto image = test::render(torus, fields, 0.4f, camera, s, kSize, kSize);
        test::maybe_save(image, "torus_hatch_min_" + render::to_string(style));
        const Window w = measure(image, front_top, 12);
        INFO("horizontal variation " << w.horizontal << ", vertical " << w.vertical);
        CHECK(w.vertical > 3 * w.horizontal);
    }
    SECTION("cross: both directions in darker tones, ink follows the tone") {
        s.hatching = render::Hatching::Cross;
        const auto image = test::render(torus, fields, 0.4f, camera, s, kSize, kSize);
        test::maybe_save(image, "torus_hatch_cross_" + render::to_string(style));
        // Inner walls of the tube, v = 150 degrees: the right one faces away
        // from the light, the left one faces it (n = light).
        const glm::vec2 dark = test::project(camera, bounds, {0.654f, 0, 0.2f}, kSize, kSize);
        const glm::vec2 lit = test::project(camera, bounds, {-0.654f, 0, 0.2f}, kSize, kSize);
        const Window d = measure(image, dark, 10), m = measure(image, front_top, 10), l = measure(image, lit, 6);
        INFO("ink: dark side " << d.ink << ", mid tone " << m.ink << ", lit " << l.ink);
        CHECK(d.ink > 1.5 * m.ink);
        CHECK(m.ink > 2 * l.ink);
        INFO("dark side variation: horizontal " << d.horizontal << ", vertical " << d.vertical);
        CHECK(std::min(d.horizontal, d.vertical) > 0.3 * std::max(d.horizontal, d.vertical));
    }
}

TEST_CASE("hatching keeps its density on screen when the camera comes closer", "[render][hatching]") {
    // Strokes grow from surface samples: coming 2.5 times closer must add
    // samples so that the ink per pixel over the same surface patch stays.
    const Mesh torus = make_torus(1.0f, 0.4f, 160, 64);
    const SurfaceFields fields = test::torus_fields(torus, 1.0f, 0.4f);
    auto s = test::lines_only({false, false, false});
    s.hatching = render::Hatching::Max;
    s.light_dir = glm::normalize(glm::vec3(0.85f, 0, 0.53f));
    const glm::vec3 patch(0.0f, -1.0f, 0.4f);  // top of the tube, mid tone
    double ink[2];
    for (int i = 0; i < 2; ++i) {
        const float distance = i == 0 ? 5.0f : 2.0f;
        const auto camera = render::Camera::look_at(patch + glm::vec3(0, 0, distance), patch, {0, 1, 0}, 40.0f);
        const auto image = test::render(torus, fields, 0.4f, camera, s, kSize, kSize);
        test::maybe_save(image, i == 0 ? "torus_hatch_far" : "torus_hatch_near");
        // The same surface patch, 0.16 x 0.16 model units, at either distance.
        const int half = int(0.08f / (distance * std::tan(20.0f * 3.14159265f / 180.0f)) * kSize / 2);
        ink[i] = measure(image, {kSize / 2, kSize / 2}, half).ink;
    }
    INFO("ink far " << ink[0] << ", near " << ink[1]);
    CHECK(ink[0] > 0.02);
    CHECK(ink[1] > 0.7 * ink[0]);
    CHECK(ink[1] < 1.4 * ink[0]);
}

namespace {

// Gaps (in pixels) between successive ink runs along a row of the image.
std::vector<int> gaps_along_row(const render::Image& image, int y, int x0, int x1) {
    std::vector<int> gaps;
    int last_end = -1;
    bool in_ink = false;
    for (int x = x0; x <= x1; ++x) {
        const bool ink = image.at(x, y).g < 128;
        if (ink && !in_ink && last_end >= 0) gaps.push_back(x - last_end);
        if (!ink && in_ink) last_end = x;
        in_ink = ink;
    }
    return gaps;
}

}  // namespace

TEST_CASE("hatching strokes are evenly spaced streamlines", "[render][hatching]") {
    // A cylinder seen from the side, lit from the camera's side: its tone
    // changes across it, and along its axis it is constant. Max hatching runs
    // around the cylinder (d1), so each row along the axis crosses strokes at
    // a steady spacing: Jobard and Lefer's separation, not random placement.
    const Mesh tube = make_torus(20.0f, 1.0f, 1024, 64);  // a long stretch of torus is a cylinder
    const SurfaceFields fields = test::torus_fields(tube, 20.0f, 1.0f);
    const glm::vec3 at(0, -20, 0);  // on the tube's centre circle, where it runs along x
    const auto camera = render::Camera::look_at(at + glm::vec3(0, 0, 6), at, {0, 1, 0}, 40.0f);
    const auto bounds = render::bounding_sphere(tube);
    auto s = test::lines_only({false, false, false});
    s.hatching = render::Hatching::Max;
    s.light_dir = glm::normalize(glm::vec3(0, 0.6f, 0.8f));  // from above: the lower half is in shade
    s.hatch_spacing = 10;  // gaps of many pixels: the pixel grid adds little variation
    const auto image = test::render(tube, fields, 1.0f, camera, s, kSize, kSize);
    test::maybe_save(image, "tube_hatch_max");
    // The row through the tube's darker lower part (below the axis, facing
    // away from the light), over the middle half of the image.
    const glm::vec2 row = test::project(camera, bounds, at + glm::vec3(0, -0.5f, 0.85f), kSize, kSize);
    const std::vector<int> gaps = gaps_along_row(image, int(row.y), kSize / 4, 3 * kSize / 4);
    REQUIRE(gaps.size() >= 10);
    double mean = 0, var = 0;
    for (int g : gaps) mean += g;
    mean /= double(gaps.size());
    for (int g : gaps) var += (g - mean) * (g - mean);
    const double cv = std::sqrt(var / double(gaps.size())) / mean;
    INFO(gaps.size() << " gaps, mean " << mean << " px, coefficient of variation " << cv);
    CHECK(cv < 0.35);  // evenly spaced (uniformly random positions would give about 1)
}

TEST_CASE("hatching stays put when the view turns a little", "[render][hatching]") {
    // Strokes are seeded from surface points in a fixed order, so a view
    // turned by half a degree shows nearly the same strokes.
    const Mesh torus = make_torus(1.0f, 0.4f, 160, 64);
    const SurfaceFields fields = test::torus_fields(torus, 1.0f, 0.4f);
    auto s = test::lines_only({false, false, false});
    s.hatching = render::Hatching::Cross;
    s.light_dir = glm::normalize(glm::vec3(0.85f, 0, 0.53f));
    render::Image images[2];
    for (int i = 0; i < 2; ++i) {
        const float a = glm::radians(0.5f * float(i));
        const glm::vec3 eye = 4.0f * glm::vec3(std::sin(a), -0.5f, std::cos(a));
        images[i] = test::render(torus, fields, 0.4f, render::Camera::look_at(eye, {0, 0, 0}, {0, 1, 0}, 40.0f), s,
                                 kSize, kSize);
    }
    const double there = render::ink_within(images[0], images[1], 2.0f), back = render::ink_within(images[1], images[0], 2.0f);
    INFO("ink within 2 px after turning 0.5 degrees: " << there << ", and back: " << back);
    CHECK(there > 0.85);
    CHECK(back > 0.85);
}

TEST_CASE("hatching strokes are the same with back faces culled from the field pass", "[render][hatching][clusters]") {
    const render::BoundingSphere bounds = test::upload_shared_bunny();
    render::Renderer& r = test::renderer();
    const glm::vec3 c = bounds.center;
    const float d = 2.5f * bounds.radius;
    render::RenderSettings s = test::lines_only({false, false, false, false});
    s.hatching = render::Hatching::Cross;
    for (const glm::vec3 eye : {c + glm::vec3(0, 0, d), c + glm::vec3(0.3f, -1.0f, 0.2f) * d}) {  // front; into the holes
        const render::Camera camera = render::Camera::look_at(eye, c, glm::vec3(0, 1, 0), 30.0f);
        r.set_back_face_culling(false);
        const std::vector<render::Stroke> every = r.hatch_strokes(camera, s, 400, 300);
        r.set_back_face_culling(true);
        const std::vector<render::Stroke> culled = r.hatch_strokes(camera, s, 400, 300);
        size_t points = 0, same = 0;
        for (size_t i = 0; i < std::min(every.size(), culled.size()); ++i) {
            points += every[i].points.size();
            if (every[i].points == culled[i].points) same += every[i].points.size();
        }
        INFO(every.size() << " strokes, " << points << " points, " << same << " the same");
        CHECK(every.size() > 50);
        CHECK(culled.size() == every.size());
        CHECK(same == points);
    }
}

TEST_CASE("shader hatching drawn once a pixel matches the surface pass's per-fragment strokes", "[render][hatching]") {
    // Software GL draws --hatch-style shader in the surface pass; a GPU from
    // targets the surface pass fills, in one full-screen pass
    // (render/hatching/shader_hatching.h): the same strokes from the same
    // directions and tone, once a pixel instead of per fragment. With 4x
    // multisampling the targets are resolved (averaged) first.
    const Mesh torus = make_torus(1.0f, 0.4f, 160, 64);
    const SurfaceFields fields = test::torus_fields(torus, 1.0f, 0.4f);
    const auto camera = render::Camera::look_at({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40.0f);
    auto s = test::lines_only({false, false, false});
    s.light_dir = glm::normalize(glm::vec3(0.85f, 0, 0.53f));
    s.hatching = render::Hatching::Cross;
    s.hatch_style = render::HatchStyle::Shader;
    render::Renderer& r = test::renderer();
    r.set_hatching_in_surface(true);
    const auto in_surface = test::render(torus, fields, 0.4f, camera, s, kSize, kSize);
    r.set_hatching_in_surface(false);
    const auto deferred = test::render(torus, fields, 0.4f, camera, s, kSize, kSize);
    s.msaa = true;
    const auto deferred_msaa = test::render(torus, fields, 0.4f, camera, s, kSize, kSize);
    r.set_hatching_in_surface(true);
    test::maybe_save(in_surface, "torus_shader_in_surface");
    test::maybe_save(deferred, "torus_shader_deferred");
    const size_t ink = test::count_ink(in_surface);
    const double near = render::ink_within(in_surface, deferred, 1.0f), back = render::ink_within(deferred, in_surface, 1.0f);
    INFO(ink << " ink pixels; within 1 px: " << near << ", back " << back);
    CHECK(ink > 5000);
    CHECK(near > 0.95);
    CHECK(back > 0.95);
    const double msaa_near = render::ink_within(in_surface, deferred_msaa, 1.0f);
    const double msaa_back = render::ink_within(deferred_msaa, in_surface, 1.0f);
    INFO("multisampled: within 1 px " << msaa_near << ", back " << msaa_back);
    CHECK(msaa_near > 0.95);
    CHECK(msaa_back > 0.95);
}
