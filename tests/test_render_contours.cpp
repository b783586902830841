// Occluding contours: a sphere's contour is the circle the camera predicts,
// closed and one line width wide.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"
#include "test_support.h"

#include "geometry/mesh/primitives.h"

#include <glm/trigonometric.hpp>

#include <cmath>

using namespace kappa;

namespace {

// Radius in pixels of the silhouette of a sphere of radius R seen from
// distance D with vertical field of view fov over `height` pixels: the
// tangent cone has half-angle asin(R / D).
double predicted_radius(double R, double D, double fov_deg, int height) {
    return 0.5 * height * std::tan(std::asin(R / D)) / std::tan(glm::radians(fov_deg) * 0.5);
}

}  // namespace

TEST_CASE("a sphere's contour is a closed circle of the predicted radius, one line wide", "[render][contours]") {
    const int size = 256;
    const float line_width = GENERATE(2.0f, 3.0f);
    const Mesh sphere = make_icosphere(1.0f, 4);
    const auto camera = render::Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30.0f);
    auto settings = test::lines_only({true, false, false});
    settings.line_width = line_width;
    const render::Image image = test::render(sphere, test::sphere_fields(sphere, 1.0f), 1.0f, camera, settings, size, size);
    test::maybe_save(image, "sphere_contour_w" + std::to_string(int(line_width)));

    const double expected = predicted_radius(1.0, 5.0, 30.0, size);
    const double cx = size * 0.5, cy = size * 0.5;
    // Every ink pixel lies on the circle, within half the line width plus a pixel.
    size_t ink = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            if (test::is_ink(image.at(x, y))) {
                ++ink;
                const double r = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
                INFO("ink at (" << x << ", " << y << "), radius " << r << ", expected " << expected);
                REQUIRE(std::abs(r - expected) <= 0.5 * line_width + 1.0);
            }
    // Closed and of constant width: along every ray from the centre the line
    // crosses the circle once, as a run of about line_width ink pixels.
    for (int k = 0; k < 720; ++k) {
        const double a = 2 * M_PI * k / 720;
        int run = 0, runs = 0;
        bool inside = false;
        for (double t = expected - 8; t <= expected + 8; t += 0.25) {
            const int x = int(std::floor(cx + t * std::cos(a))), y = int(std::floor(cy + t * std::sin(a)));
            const bool on = test::is_ink(image.at(x, y));
            if (on) run++;
            if (on && !inside) runs++;
            inside = on;
        }
        const double width = run * 0.25;
        INFO("ray at " << glm::degrees(a) << " degrees: ink width " << width << " px in " << runs << " runs");
        REQUIRE(runs == 1);
        REQUIRE(width >= line_width - 1.0);
        REQUIRE(width <= line_width + 1.5);
    }
    // The whole circle is drawn: about circumference * width ink pixels.
    const double area = 2 * M_PI * expected * line_width;
    CHECK(double(ink) > 0.8 * area);
    CHECK(double(ink) < 1.3 * area);
}
