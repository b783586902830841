// View-dependent lines beyond contours (shaders/lines/isolines_geom.glsl,
// shaders/lines/view_ridges_geom.glsl) where the mathematics puts them:
//   - a corrugated sheet z = h sin(k x) seen from a camera tilted towards
//     +x: the projected view direction w runs along +x everywhere, kr is the
//     curvature along x, zero on the inflection lines x = n pi / k, and
//     Dw kr = d kr / dx has the sign of cos(k x): suggestive contours at
//     x = 0, +-2 pi / k, suggestive highlights at x = +-pi / k; Dw kr = 0 on
//     the crests and troughs x = pi / 2k + n pi / k;
//   - a prolate spheroid seen from the side: d1 runs around the long axis,
//     and v.d1 = 0 on the symmetry plane that holds the eye: its principal
//     highlight is the line along the middle of the image;
//   - an ellipsoid thin across x and deep along the view: its view-dependent
//     curvature peaks on its sharp front edge (the plane x = 0, a maximum
//     across it when the depth exceeds 1.22 times the thickness), so the
//     apparent ridge is the image's vertical centre line, besides the lines
//     that follow the contour; a sphere's only apparent ridge is its outline.
#include "test_render_fixtures.h"

#include "geometry/mesh/primitives.h"
#include "geometry/surface_analysis.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

using namespace kappa;

namespace {

render::LineSelection none_but(bool render::LineSelection::*kind) {
    render::LineSelection l{false, false, false, false, false, false, false, false, false, false, false};
    l.*kind = true;
    return l;
}

// z = h sin(k x) over [-1.25, 1.25]^2, one wavelength 2 pi / k = 1.
constexpr float kHeight = 0.1f, kWave = 2.0f * float(M_PI);

Mesh corrugated_sheet() {
    Mesh m = make_grid(2.5f, 200);
    for (glm::vec3& p : m.positions) p.z = kHeight * std::sin(kWave * p.x);
    return m;
}

// Tilted 50 degrees towards +x: steeper than the sheet's slopes (32 degrees),
// so w points along +x and every point faces the camera.
render::Camera tilted_camera() {
    const float a = 50.0f * float(M_PI) / 180.0f;
    return render::Camera::look_at({8.0f * std::sin(a), 0, 8.0f * std::cos(a)}, {0, 0, 0}, {0, 1, 0}, 22);
}

struct InkCheck {
    size_t ink = 0;
    double near = 0;      // fraction of the ink within `radius` of the expected curves
    double covered = 0;   // fraction of the curves' sample points with ink within `radius`
};

// Compares the ink with sample points of the expected curves.
InkCheck check_ink(const render::Image& im, const std::vector<glm::vec2>& curve, float radius,
                   const std::function<bool(glm::vec2)>& counted = nullptr) {
    InkCheck r;
    size_t near = 0;
    std::vector<char> hit(curve.size(), 0);
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const glm::vec2 p(x + 0.5f, y + 0.5f);
            if (!test::is_ink(im.at(x, y)) || (counted && !counted(p))) continue;
            ++r.ink;
            bool on = false;
            for (size_t i = 0; i < curve.size(); ++i)
                if (glm::length(curve[i] - p) < radius) on = true, hit[i] = 1;
            near += on;
        }
    size_t covered = 0;
    for (char h : hit) covered += h;
    r.near = r.ink ? double(near) / double(r.ink) : 0.0;
    r.covered = curve.empty() ? 0.0 : double(covered) / double(curve.size());
    return r;
}

// Sample points of the sheet's lines x = const, across the sheet.
std::vector<glm::vec2> sheet_lines(const render::Camera& camera, const render::BoundingSphere& bounds,
                                   const std::vector<float>& xs, int width, int height) {
    std::vector<glm::vec2> pts;
    for (float x : xs)
        for (int i = 0; i <= 200; ++i) {
            const float y = -1.25f + 2.5f * float(i) / 200.0f;
            pts.push_back(test::project(camera, bounds, {x, y, kHeight * std::sin(kWave * x)}, width, height));
        }
    return pts;
}

}  // namespace

TEST_CASE("A corrugated sheet draws suggestive highlights on the inflection lines where kr falls towards the eye",
          "[render][view-lines]") {
    const Mesh sheet = corrugated_sheet();
    const SurfaceFields fields = compute_surface_fields(sheet);
    const render::BoundingSphere bounds = render::bounding_sphere(sheet);
    const render::Camera camera = tilted_camera();
    const float fs = 1.0f / (kHeight * kWave * kWave);  // the smallest radius of curvature
    const render::Image im = test::render(sheet, fields, fs, camera,
                                          test::lines_only(none_but(&render::LineSelection::suggestive_highlights)),
                                          320, 320);
    test::maybe_save(im, "suggestive-highlights-sheet");
    const InkCheck highlights = check_ink(im, sheet_lines(camera, bounds, {-0.5f, 0.5f}, 320, 320), 3.0f);
    INFO("ink " << highlights.ink << ", near x = +-1/2: " << highlights.near << ", covered " << highlights.covered);
    CHECK(highlights.ink > 300);
    CHECK(highlights.near > 0.95);
    CHECK(highlights.covered > 0.8);

    // The other half of kr's zeros are the suggestive contours, at x = 0 and +-1.
    const render::Image sc = test::render(sheet, fields, fs, camera,
                                          test::lines_only(none_but(&render::LineSelection::suggestive)), 320, 320);
    test::maybe_save(sc, "suggestive-sheet");
    const InkCheck contours = check_ink(sc, sheet_lines(camera, bounds, {-1.0f, 0.0f, 1.0f}, 320, 320), 3.0f);
    INFO("suggestive contours: ink " << contours.ink << ", near x = 0, +-1: " << contours.near);
    CHECK(contours.ink > 300);
    CHECK(contours.near > 0.95);
}

TEST_CASE("A corrugated sheet draws its Dw kr = 0 lines on the crests and troughs", "[render][view-lines]") {
    const Mesh sheet = corrugated_sheet();
    const SurfaceFields fields = compute_surface_fields(sheet);
    const render::BoundingSphere bounds = render::bounding_sphere(sheet);
    const render::Camera camera = tilted_camera();
    render::RenderSettings s = test::lines_only(none_but(&render::LineSelection::dwkr));
    s.sc_threshold = 0.0f;
    const render::Image im = test::render(sheet, fields, 1.0f / (kHeight * kWave * kWave), camera, s, 320, 320);
    test::maybe_save(im, "dwkr-sheet");
    // Within |x| < 1 (the crests at the sheet's edges x = +-1.25 have one-sided estimates).
    const float left = test::project(camera, bounds, {-1, 0, 0}, 320, 320).x;
    const float right = test::project(camera, bounds, {1, 0, 0}, 320, 320).x;
    const InkCheck r = check_ink(im, sheet_lines(camera, bounds, {-0.75f, -0.25f, 0.25f, 0.75f}, 320, 320), 3.0f,
                                 [&](glm::vec2 p) { return p.x > left && p.x < right; });
    INFO("ink " << r.ink << ", near the crests and troughs " << r.near << ", covered " << r.covered);
    CHECK(r.ink > 400);
    CHECK(r.near > 0.95);
    CHECK(r.covered > 0.8);
}

TEST_CASE("A prolate spheroid seen from the side has its principal highlight along its middle",
          "[render][view-lines]") {
    const float a = 1.6f, b = 0.5f;
    const Mesh spheroid = make_ellipsoid(a, b, b, 5);
    const SurfaceFields fields = compute_surface_fields(spheroid);
    const render::BoundingSphere bounds = render::bounding_sphere(spheroid);
    const render::Camera camera = render::Camera::look_at({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 40);
    const render::Image im = test::render(spheroid, fields, b, camera,
                                          test::lines_only(none_but(&render::LineSelection::principal_highlights)),
                                          256, 256);
    test::maybe_save(im, "principal-highlights-spheroid");
    // The front half of the plane y = 0: (x, 0, b sqrt(1 - x^2/a^2)); drawn
    // at least away from the umbilic tips, where k1 = k2 fails the test.
    auto middle = [&](float reach) {
        std::vector<glm::vec2> pts;
        for (int i = 0; i <= 200; ++i) {
            const float x = a * reach * (-1.0f + 2.0f * float(i) / 200.0f);
            pts.push_back(test::project(camera, bounds, {x, 0, b * std::sqrt(1 - x * x / (a * a))}, 256, 256));
        }
        return pts;
    };
    const InkCheck r = check_ink(im, middle(1.0f), 3.0f), inner = check_ink(im, middle(0.7f), 3.0f);
    INFO("ink " << r.ink << ", near the middle line " << r.near << ", covered (|x| < 0.7 a) " << inner.covered);
    CHECK(r.ink > 200);
    CHECK(r.near > 0.97);
    CHECK(inner.covered > 0.97);
}

TEST_CASE("Apparent ridges: a thin deep ellipsoid's sharp front edge, a sphere's outline", "[render][view-lines]") {
    const float a = 0.35f, b = 1.0f, c = 1.0f;
    const Mesh ellipsoid = make_ellipsoid(a, b, c, 5);
    const SurfaceFields fields = compute_surface_fields(ellipsoid);
    const render::BoundingSphere bounds = render::bounding_sphere(ellipsoid);
    const render::Camera camera = render::Camera::look_at({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 40);
    const render::Image im = test::render(ellipsoid, fields, a, camera,
                                          test::lines_only(none_but(&render::LineSelection::apparent_ridges)), 256,
                                          256);
    test::maybe_save(im, "apparent-ridges-ellipsoid");
    // The front edge: (0, y, c sqrt(1 - y^2/b^2)); inside the outline (the
    // projected ellipse of semi-axes a, b shrunk to 80%) only it should be drawn.
    std::vector<glm::vec2> edge;
    for (int i = 0; i <= 200; ++i) {
        const float y = b * (-0.7f + 1.4f * float(i) / 200.0f);
        edge.push_back(test::project(camera, bounds, {0, y, c * std::sqrt(1 - y * y / (b * b))}, 256, 256));
    }
    const glm::vec2 centre = test::project(camera, bounds, {0, 0, 0}, 256, 256);
    const glm::vec2 semi = test::project(camera, bounds, {a, b, 0}, 256, 256) - centre;
    auto inside = [&](glm::vec2 p) {
        const glm::vec2 q = (p - centre) / glm::abs(semi);
        return glm::dot(q, q) < 0.8f * 0.8f;
    };
    const InkCheck r = check_ink(im, edge, 3.0f, inside);
    INFO("ink inside the outline " << r.ink << ", near the front edge " << r.near << ", covered " << r.covered);
    CHECK(r.ink > 150);
    CHECK(r.near > 0.95);
    CHECK(r.covered > 0.9);

    // A sphere (exact fields): q1 = 1 / (R^2 cos^2(theta)) only grows towards the outline.
    const float R = 1.0f;
    const Mesh sphere = make_icosphere(R, 5);
    const render::Camera far = render::Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30);
    const render::Image sp = test::render(sphere, test::sphere_fields(sphere, R), R, far,
                                          test::lines_only(none_but(&render::LineSelection::apparent_ridges)), 256,
                                          256);
    test::maybe_save(sp, "apparent-ridges-sphere");
    // The outline: the circle where n.v = 0, radius sqrt(R^2 - R^4 / 25) at z = R^2 / 5.
    std::vector<glm::vec2> outline;
    const float z = R * R / 5.0f, rho = std::sqrt(R * R - z * z);
    for (int i = 0; i < 720; ++i) {
        const float t = 2.0f * float(M_PI) * float(i) / 720.0f;
        outline.push_back(test::project(far, render::bounding_sphere(sphere), {rho * std::cos(t), rho * std::sin(t), z},
                                        256, 256));
    }
    const InkCheck o = check_ink(sp, outline, 3.0f);
    INFO("sphere: ink " << o.ink << ", near the outline " << o.near << ", covered " << o.covered);
    CHECK(o.ink > 300);
    CHECK(o.near > 0.97);
    CHECK(o.covered > 0.9);
}
