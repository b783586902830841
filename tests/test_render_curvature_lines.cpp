// Ridges, valleys, parabolic and mean-zero lines (shaders/lines/curvature_lines_geom.glsl)
// where the mathematics puts them: a torus's parabolic lines are its top and
// bottom circles (cos v = 0), its mean-zero lines the circles where
// cos v = -R / 2r; an ellipsoid's ridges and valleys lie in its symmetry planes.
#include "test_render_fixtures.h"

#include "geometry/mesh/primitives.h"
#include "geometry/curvature/feature_size.h"
#include "geometry/surface_analysis.h"

#include <glm/gtc/matrix_transform.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace kappa;

namespace {

render::LineSelection only(bool render::LineSelection::*kind) {
    render::LineSelection l{false, false, false, false, false, false, false, false};
    l.*kind = true;
    return l;
}

// Fraction of the ink within r px of any of the given points (pixels), sampling curves.
double ink_near_points(const render::Image& im, const std::vector<glm::vec2>& points, float r, size_t* ink_out) {
    size_t ink = 0, near = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            if (!test::is_ink(im.at(x, y))) continue;
            ++ink;
            for (const glm::vec2& c : points)
                if (glm::length(c - glm::vec2(x + 0.5f, y + 0.5f)) < r) {
                    ++near;
                    break;
                }
        }
    *ink_out = ink;
    return ink ? double(near) / double(ink) : 0.0;
}

// Fraction of the ink within `r` px of the projected circle of radius rho at
// height z around the z axis, and the ink count.
std::pair<double, size_t> ink_near_circle(const render::Image& im, const render::Camera& camera,
                                          const render::BoundingSphere& bounds, float rho, float z, float r) {
    std::vector<glm::vec2> circle;
    for (int i = 0; i < 720; ++i) {
        const float a = 2.0f * float(M_PI) * float(i) / 720.0f;
        circle.push_back(test::project(camera, bounds, {rho * std::cos(a), rho * std::sin(a), z}, im.width, im.height));
    }
    size_t ink = 0;
    const double near = ink_near_points(im, circle, r, &ink);
    return {near, ink};
}

}  // namespace

TEST_CASE("A torus draws its parabolic lines on its top and bottom circles", "[render][curvature-lines]") {
    const float R = 1.0f, r = 0.4f;
    const Mesh torus = make_torus(R, r, 160, 64);
    const SurfaceFields exact = test::torus_fields(torus, R, r);
    const render::BoundingSphere bounds = render::bounding_sphere(torus);
    // From above: the top circle (v = 90 degrees) is the circle of radius R at z = r.
    const render::Camera camera = render::Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40);
    const render::Image im = test::render(torus, exact, r, camera, test::lines_only(only(&render::LineSelection::parabolic)), 256, 256);
    test::maybe_save(im, "parabolic-torus");
    const auto [near, ink] = ink_near_circle(im, camera, bounds, R, r, 2.5f);
    INFO("ink " << ink << ", near the top circle " << near);
    CHECK(ink > 300);  // a circle of ~140 px radius, 2 px wide
    CHECK(near > 0.97);
}

TEST_CASE("A torus draws its mean-zero lines where cos v = -R / 2r", "[render][curvature-lines]") {
    const float R = 1.0f, r = 0.6f;
    const Mesh torus = make_torus(R, r, 160, 64);
    const SurfaceFields exact = test::torus_fields(torus, R, r);
    const render::BoundingSphere bounds = render::bounding_sphere(torus);
    const render::Camera camera = render::Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40);
    const render::Image im = test::render(torus, exact, r, camera, test::lines_only(only(&render::LineSelection::mean_zero)), 256, 256);
    test::maybe_save(im, "mean-zero-torus");
    // H = 0: 1/r + cos v / (R + r cos v) = 0, cos v = -R / (2 r), on the inner side, top half seen.
    const float cv = -R / (2 * r), sv = std::sqrt(1 - cv * cv);
    const auto [near, ink] = ink_near_circle(im, camera, bounds, R + r * cv, r * sv, 2.5f);
    INFO("ink " << ink << ", near the circle " << near);
    CHECK(ink > 100);
    CHECK(near > 0.97);
}

TEST_CASE("An ellipsoid's ridges and valleys lie in its symmetry planes", "[render][curvature-lines]") {
    const Mesh ellipsoid = make_ellipsoid(1.6f, 1.0f, 0.6f, 5);
    const SurfaceFields fields = compute_surface_fields(ellipsoid);
    const render::BoundingSphere bounds = render::bounding_sphere(ellipsoid);
    // Looking down z: the planes x = 0 and y = 0 appear as the two lines
    // through the image centre, and the plane z = 0 meets the surface in the
    // ellipse x^2/a^2 + y^2/b^2 = 1, the outline.
    const render::Camera camera = render::Camera::look_at({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 40);
    render::LineSelection l = only(&render::LineSelection::ridges);
    l.valleys = true;
    render::RenderSettings s = test::lines_only(l);
    s.rv_threshold = 0.5f;
    const render::Image im = test::render(ellipsoid, fields, 0.6f, camera, s, 256, 256);
    test::maybe_save(im, "ridges-ellipsoid");
    const glm::vec2 c = test::project(camera, bounds, {0, 0, 0}, 256, 256);
    std::vector<glm::vec2> equator;
    for (int i = 0; i < 720; ++i) {
        const float t = 2.0f * float(M_PI) * float(i) / 720.0f;
        equator.push_back(test::project(camera, bounds, {1.6f * std::cos(t), 1.0f * std::sin(t), 0.0f}, 256, 256));
    }
    size_t ink = 0, near = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            if (!test::is_ink(im.at(x, y))) continue;
            ++ink;
            const glm::vec2 p(x + 0.5f, y + 0.5f);
            bool on = std::fabs(p.x - c.x) < 3.0f || std::fabs(p.y - c.y) < 3.0f;
            for (size_t i = 0; i < equator.size() && !on; ++i) on = glm::length(equator[i] - p) < 3.0f;
            near += on;
        }
    INFO("ink " << ink << ", on the symmetry planes " << double(near) / double(std::max<size_t>(ink, 1)));
    CHECK(ink > 100);
    CHECK(double(near) > 0.9 * double(ink));
}

TEST_CASE("A sphere's isophotes are circles around the light direction, its topographic lines circles of latitude",
          "[render][curvature-lines]") {
    const float R = 1.0f;
    const Mesh sphere = make_icosphere(R, 5);
    const SurfaceFields exact = test::sphere_fields(sphere, R);
    const render::BoundingSphere bounds = render::bounding_sphere(sphere);
    // Camera on +z; the light towards the viewer: n.l = z / R in model coordinates.
    const render::Camera camera = render::Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30);
    render::LineSelection l{false, false, false, false, false, false, false, false, true, false};
    render::RenderSettings s = test::lines_only(l);
    s.light_dir = {0, 0, 1};
    s.isophote_count = 4;
    const render::Image iso = test::render(sphere, exact, R, camera, s, 256, 256);
    test::maybe_save(iso, "isophotes-sphere");
    std::vector<glm::vec2> circles;
    for (int k = 1; k <= 4; ++k) {
        const float z = (float(k) - 0.5f) / 4.0f * R, rho = std::sqrt(R * R - z * z);
        for (int i = 0; i < 360; ++i) {
            const float a = 2.0f * float(M_PI) * float(i) / 360.0f;
            circles.push_back(test::project(camera, bounds, {rho * std::cos(a), rho * std::sin(a), z}, 256, 256));
        }
    }
    size_t ink = 0;
    double near = ink_near_points(iso, circles, 2.5f, &ink);
    INFO("isophotes: ink " << ink << ", near the four circles " << near);
    CHECK(ink > 400);
    CHECK(near > 0.97);

    // Topographic lines: heights y = -R + (k - 1/2) 2R / N, seen from +z.
    l.isophotes = false;
    l.topo = true;
    s = test::lines_only(l);
    s.topo_count = 6;
    const render::Image topo = test::render(sphere, exact, R, camera, s, 256, 256);
    test::maybe_save(topo, "topo-sphere");
    std::vector<glm::vec2> latitudes;
    for (int k = 1; k <= 6; ++k) {
        const float y = -bounds.radius + (float(k) - 0.5f) * 2.0f * bounds.radius / 6.0f + bounds.center.y;
        const float rho = std::sqrt(std::max(0.0f, R * R - y * y));
        for (int i = 0; i < 360; ++i) {
            const float a = 2.0f * float(M_PI) * float(i) / 360.0f;
            latitudes.push_back(test::project(camera, bounds, {rho * std::cos(a), y, rho * std::sin(a)}, 256, 256));
        }
    }
    near = ink_near_points(topo, latitudes, 2.5f, &ink);
    INFO("topo: ink " << ink << ", near the six latitudes " << near);
    CHECK(ink > 300);
    CHECK(near > 0.97);
}

TEST_CASE("Ridges alone are a corrugated sheet's crests, valleys alone its troughs", "[render][curvature-lines]") {
    // z = A sin(2 pi x / L), normals up: k = A (2 pi / L)^2 > 0 across the
    // crests (sin = 1, convex seen from above: ridges), < 0 across the
    // troughs (valleys); zero along y. Seen from above, each kind alone is a
    // set of lines x = constant: crests at x = L/4 + m L, troughs at 3L/4 + m L.
    // A ridge/valley sign swap, or one kind drawing the other, fails.
    const float A = 0.08f, L = 0.5f;
    Mesh sheet = make_grid(2.0f, 100);
    for (glm::vec3& p : sheet.positions) p.z = A * std::sin(2.0f * float(M_PI) * p.x / L);
    const SurfaceFields fields = compute_surface_fields(sheet);
    {
        size_t up = 0;  // the grid is counter-clockwise seen from +z: normals up
        for (const glm::vec3& n : fields.normals) up += n.z > 0;
        REQUIRE(up == fields.size());
    }
    const render::BoundingSphere bounds = render::bounding_sphere(sheet);
    const render::Camera camera = render::Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30);
    auto screen_x = [&](float x) { return test::project(camera, bounds, {x, 0, 0}, 256, 256).x; };
    const float border = screen_x(0.9f) - screen_x(0.0f);  // leave out the sheet's border (one-sided estimates)
    const float centre = screen_x(0.0f), centre_y = test::project(camera, bounds, {0, 0, 0}, 256, 256).y;
    for (const bool ridges : {true, false}) {
        render::LineSelection l = only(ridges ? &render::LineSelection::ridges : &render::LineSelection::valleys);
        render::RenderSettings s = test::lines_only(l);
        s.lines.creases = false;
        s.rv_threshold = 0.2f;
        s.detail = 0;
        const render::Image im = test::render(sheet, fields, feature_size(sheet, fields), camera, s, 256, 256);
        test::maybe_save(im, ridges ? "ridges-sheet" : "valleys-sheet");
        size_t ink = 0, on_crests = 0, on_troughs = 0;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) {
                if (!test::is_ink(im.at(x, y))) continue;
                const glm::vec2 p(x + 0.5f, y + 0.5f);
                if (std::fabs(p.x - centre) > border || std::fabs(p.y - centre_y) > border) continue;
                ++ink;
                for (int m = -2; m <= 2; ++m) {
                    on_crests += std::fabs(p.x - screen_x(L / 4 + float(m) * L)) < 3.0f;
                    on_troughs += std::fabs(p.x - screen_x(3 * L / 4 + float(m) * L)) < 3.0f;
                }
            }
        INFO((ridges ? "ridges" : "valleys") << ": ink " << ink << ", on crests " << on_crests << ", on troughs "
                                             << on_troughs);
        CHECK(ink > 400);  // about 4 lines of ~200 px, 2 px wide
        CHECK(double(ridges ? on_crests : on_troughs) > 0.95 * double(ink));
        CHECK((ridges ? on_troughs : on_crests) == 0);
    }
}
