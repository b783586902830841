// Suggestive contours: none on a sphere or a plane, only on the inner
// (negatively curved) half of a torus, and never more ink for a higher
// threshold.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"
#include "test_support.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/mesh/primitives.h"
#include "geometry/surface_analysis.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

using namespace kappa;

namespace {

const render::Camera kTorusView = render::Camera::look_at({0, -2.8f, 1.6f}, {0, 0, 0}, {0, 0, 1}, 40.0f);

// Torus R = 1, r = 0.4 with exact fields; fs = r as geometry/curvature/feature_size.h gives.
struct Torus {
    Mesh mesh = make_torus(1.0f, 0.4f, 160, 64);
    SurfaceFields fields = test::torus_fields(mesh, 1.0f, 0.4f);
};

}  // namespace

TEST_CASE("a sphere has no suggestive contours", "[render][suggestive]") {
    const Mesh sphere = make_icosphere(1.0f, 4);
    const auto camera = render::Camera::look_at({0.3f, 0.8f, 4}, {0, 0, 0}, {0, 1, 0}, 35.0f);
    auto settings = test::lines_only({false, true, false});
    settings.sc_threshold = 0;  // even with no threshold at all
    SECTION("exact fields") {
        const auto image = test::render(sphere, test::sphere_fields(sphere, 1.0f), 1.0f, camera, settings);
        CHECK(test::count_ink(image) == 0);
    }
    SECTION("estimated fields") {
        const SurfaceFields fields = compute_surface_fields(sphere);
        const auto image = test::render(sphere, fields, feature_size(sphere, fields), camera, settings);
        CHECK(test::count_ink(image) == 0);
    }
}

TEST_CASE("a flat grid has no lines", "[render][suggestive][contours]") {
    const Mesh grid = make_grid(2.0f, 40);
    const auto camera = render::Camera::look_at({0.2f, -1.8f, 1.5f}, {0, 0, 0}, {0, 0, 1}, 40.0f);
    const auto settings = test::lines_only({true, true, false});
    SECTION("exact fields") {
        CHECK(test::count_ink(test::render(grid, test::flat_fields(grid), 1.0f, camera, settings)) == 0);
    }
    SECTION("estimated fields") {
        const SurfaceFields fields = compute_surface_fields(grid);
        const auto image = test::render(grid, fields, feature_size(grid, fields), camera, settings);
        test::maybe_save(image, "grid_lines");
        CHECK(test::count_ink(image) == 0);
    }
}

// The point of the torus (R, r around z) seen through pixel (x, y), by sphere
// tracing its distance function; false when the ray misses.
bool torus_hit(const render::Camera& camera, int width, int height, float x, float y, float R, float r,
               glm::vec3& hit) {
    const glm::mat4 inv_view = glm::inverse(camera.view);
    const float t = std::tan(glm::radians(camera.fov_y_deg) * 0.5f);
    const glm::vec3 dir_cam(((x / width) * 2 - 1) * t * width / height, (1 - (y / height) * 2) * t, -1);
    const glm::vec3 origin = glm::vec3(inv_view[3]);
    const glm::vec3 dir = glm::normalize(glm::vec3(inv_view * glm::vec4(dir_cam, 0)));
    float s = 0;
    for (int i = 0; i < 256 && s < 20; ++i) {
        const glm::vec3 p = origin + s * dir;
        const float d = glm::length(glm::vec2(glm::length(glm::vec2(p.x, p.y)) - R, p.z)) - r;
        if (d < 1e-5f) {
            hit = p;
            return true;
        }
        s += d;
    }
    return false;
}

TEST_CASE("a torus seen from above at an angle has suggestive contours on its inner half only",
          "[render][suggestive]") {
    const Torus torus;
    const auto settings = test::lines_only({false, true, false});
    const auto lines = test::render(torus.mesh, torus.fields, 0.4f, kTorusView, settings);
    test::maybe_save(lines, "torus_suggestive");

    // Where each line pixel is on the torus: v, the angle around the tube
    // (cos v < 0 on the inner half, where K < 0).
    size_t ink = 0, inner = 0, clearly_outer = 0;
    for (int y = 0; y < lines.height; ++y)
        for (int x = 0; x < lines.width; ++x) {
            if (!test::is_ink(lines.at(x, y))) continue;
            ++ink;
            glm::vec3 p;
            // The line may overhang the silhouette by half its width: try the neighbours too.
            bool found = false;
            for (int k = 0; k < 9 && !found; ++k)
                found = torus_hit(kTorusView, lines.width, lines.height, x + 0.5f + float(k % 3 - 1),
                                  y + 0.5f + float(k / 3 - 1), 1.0f, 0.4f, p);
            if (!found) continue;
            const float cos_v = (glm::length(glm::vec2(p.x, p.y)) - 1.0f) / 0.4f;
            inner += cos_v < 0;
            clearly_outer += cos_v > 0.1f;  // more than a line width from the parabolic circle
        }
    INFO("ink " << ink << ", inner half " << inner << ", clearly outer " << clearly_outer);
    CHECK(ink > 150);               // there are suggestive contours
    CHECK(inner > 0.9 * ink);       // on the inner half
    CHECK(clearly_outer == 0);      // and nowhere on the outer half
}

TEST_CASE("raising the suggestive-contour threshold never adds line pixels", "[render][suggestive]") {
    const Torus torus;
    const Mesh blob = make_ellipsoid(1.0f, 0.6f, 0.8f, 4);
    const bool fade = GENERATE(false, true);
    auto settings = test::lines_only({false, true, false});
    settings.fade = fade;
    for (int shape = 0; shape < 2; ++shape) {
        const Mesh& mesh = shape == 0 ? torus.mesh : blob;
        const SurfaceFields fields = shape == 0 ? torus.fields : compute_surface_fields(blob);
        const float fs = shape == 0 ? 0.4f : feature_size(blob, fields);
        const auto camera = shape == 0 ? kTorusView
                                       : render::Camera::look_at({1.5f, 1.0f, 3.0f}, {0, 0, 0}, {0, 1, 0}, 35.0f);
        render::Image previous;
        size_t previous_ink = 0;
        for (float s : {0.0f, 0.02f, 0.05f, 0.1f, 0.2f, 0.5f, 1.0f}) {
            settings.sc_threshold = s;
            const auto image = test::render(mesh, fields, fs, camera, settings);
            const size_t ink = test::count_ink(image);
            if (!previous.pixels.empty()) {
                INFO("shape " << shape << ", fade " << fade << ", threshold " << s);
                CHECK(ink <= previous_ink);
                // Pixel by pixel: no pixel gets darker (beyond what merging segments on screen
                // may change, test_render_fixtures.h).
                size_t darker = 0;
                for (size_t i = 0; i < image.pixels.size(); i += 4)
                    darker += image.pixels[i] + test::kScreenMergeTolerance < previous.pixels[i];
                CHECK(darker == 0);
            }
            previous = image;
            previous_ink = ink;
        }
    }
}

TEST_CASE("the same render twice is identical", "[render]") {
    const Torus torus;
    render::RenderSettings settings;  // defaults: Lambert, contours + suggestive, MSAA
    settings.hatching = render::Hatching::Cross;
    const auto a = test::render(torus.mesh, torus.fields, 0.4f, kTorusView, settings);
    const auto b = test::render(torus.mesh, torus.fields, 0.4f, kTorusView, settings);
    CHECK(a.pixels == b.pixels);
}
