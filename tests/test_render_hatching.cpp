// Principal-direction hatching: strokes follow the chosen principal
// direction in the image, and there is more ink where the tone is darker.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"

#include "geometry/primitives.h"

#include <glm/geometric.hpp>

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
    // direction d2 across it. The light comes from the right.
    const Mesh torus = make_torus(1.0f, 0.4f, 160, 64);
    const SurfaceFields fields = test::torus_fields(torus, 1.0f, 0.4f);
    const auto camera = render::Camera::look_at({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40.0f);
    const auto bounds = render::bounding_sphere(torus);
    auto s = test::lines_only({false, false, false});
    s.light_dir = glm::normalize(glm::vec3(0.85f, 0, 0.53f));
    const glm::vec2 front_top = test::project(camera, bounds, {0, -1, 0.4f}, kSize, kSize);

    SECTION("max: strokes along d1, vertical here") {
        s.hatching = render::Hatching::Max;
        const auto image = test::render(torus, fields, 0.4f, camera, s, kSize, kSize);
        test::maybe_save(image, "torus_hatch_max");
        const Window w = measure(image, front_top, 12);
        INFO("horizontal variation " << w.horizontal << ", vertical " << w.vertical);
        CHECK(w.horizontal > 3 * w.vertical);
    }
    SECTION("min: strokes along d2, horizontal here") {
        s.hatching = render::Hatching::Min;
        const auto image = test::render(torus, fields, 0.4f, camera, s, kSize, kSize);
        test::maybe_save(image, "torus_hatch_min");
        const Window w = measure(image, front_top, 12);
        INFO("horizontal variation " << w.horizontal << ", vertical " << w.vertical);
        CHECK(w.vertical > 3 * w.horizontal);
    }
    SECTION("cross: both directions in darker tones, ink follows the tone") {
        s.hatching = render::Hatching::Cross;
        const auto image = test::render(torus, fields, 0.4f, camera, s, kSize, kSize);
        test::maybe_save(image, "torus_hatch_cross");
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
