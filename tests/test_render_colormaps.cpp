// Colour maps show the colours they should at points of known curvature, and
// the colour bar shows the map's ends.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"

#include "geometry/mesh/primitives.h"

#include <algorithm>
#include <cmath>
#include <set>

using namespace kappa;

namespace {

enum class Hue { White, Red, Blue, Green, Orange };

const char* name(Hue h) {
    switch (h) {
        case Hue::White: return "white";
        case Hue::Red: return "red";
        case Hue::Blue: return "blue";
        case Hue::Green: return "green";
        case Hue::Orange: return "orange";
    }
    return "?";
}

// Which hue a pixel has, loosely: the dominant channel with a clear margin.
bool has_hue(render::Rgba c, Hue h) {
    const int r = c.r, g = c.g, b = c.b;
    switch (h) {
        case Hue::White: return std::min({r, g, b}) > 235;
        case Hue::Red: return r > 150 && r > g + 50 && r > b + 50;
        case Hue::Blue: return b > 150 && b > r + 50 && b > g + 40;
        case Hue::Green: return g > 120 && g > r + 60 && g > b + 60;
        case Hue::Orange: return r > 150 && r > b + 60 && g > b + 20 && g < r;
    }
    return false;
}

render::RenderSettings map_only(render::ColorMap map) {
    auto s = test::lines_only({false, false, false});
    s.colormap = map;
    return s;
}

Mesh inverted(Mesh m) {
    for (auto& f : m.faces) std::swap(f.y, f.z);
    return m;
}

// Exact fields of the inside of a sphere: normals inward, k1 = k2 = -1/R.
SurfaceFields inside_sphere_fields(const Mesh& mesh, float R) {
    SurfaceFields f = test::sphere_fields(mesh, R);
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
        f.normals[i] = -f.normals[i];
        f.k1[i] = f.k2[i] = -1.0f / R;
        std::swap(f.d1[i], f.d2[i]);  // keeps d1 x d2 = n
    }
    return f;
}

void check_pixel(const render::Image& image, glm::vec2 p, Hue hue, const std::string& what) {
    const auto c = image.at(int(p.x), int(p.y));
    INFO(what << ": pixel (" << int(p.x) << ", " << int(p.y) << ") is rgb(" << int(c.r) << ", " << int(c.g) << ", "
              << int(c.b) << "), expected " << name(hue));
    CHECK(has_hue(c, hue));
}

}  // namespace

TEST_CASE("colour maps on a sphere and its inside", "[render][colormap]") {
    const Mesh sphere = make_icosphere(1.0f, 3);
    const auto camera = render::Camera::look_at({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 35.0f);
    const SurfaceFields outside = test::sphere_fields(sphere, 1.0f);
    const Mesh hollow = inverted(sphere);
    const SurfaceFields inside = inside_sphere_fields(hollow, 1.0f);
    const glm::vec2 center(128.5f, 128.5f);
    struct Case {
        render::ColorMap map;
        Hue convex, concave;
    };
    // Signed maps: positive red, negative blue; the Gaussian curvature is
    // positive on both sides; the principal map: blue convex, red concave;
    // |C| = 0 is white.
    for (const Case& c : {Case{render::ColorMap::K1, Hue::Red, Hue::Blue}, Case{render::ColorMap::K2, Hue::Red, Hue::Blue},
                          Case{render::ColorMap::Mean, Hue::Red, Hue::Blue},
                          Case{render::ColorMap::Gaussian, Hue::Red, Hue::Red},
                          Case{render::ColorMap::Principal, Hue::Blue, Hue::Red},
                          Case{render::ColorMap::DCurv, Hue::White, Hue::White}}) {
        const std::string map = render::to_string(c.map);
        check_pixel(test::render(sphere, outside, 1.0f, camera, map_only(c.map)), center, c.convex, map + " outside");
        // Seen from inside: the camera within the hollow sphere.
        const auto inner_camera = render::Camera::look_at({0, 0, 0.2f}, {0, 0, -1}, {0, 1, 0}, 35.0f);
        check_pixel(test::render(hollow, inside, 1.0f, inner_camera, map_only(c.map)), center, c.concave,
                    map + " inside");
    }
}

TEST_CASE("colour maps on a torus", "[render][colormap]") {
    const Mesh torus = make_torus(1.0f, 0.4f, 120, 48);
    const SurfaceFields fields = test::torus_fields(torus, 1.0f, 0.4f);
    const auto camera = render::Camera::look_at({0, -2.8f, 1.6f}, {0, 0, 0}, {0, 0, 1}, 40.0f);
    const render::BoundingSphere bounds = render::bounding_sphere(torus);
    const auto at = [&](glm::vec3 p) { return test::project(camera, bounds, p, 256, 256); };
    const glm::vec3 outer_equator(0, -1.4f, 0), inner_wall(0, 0.6f, 0), tube_top(-1, 0, 0.4f);

    const auto gauss = test::render(torus, fields, 0.4f, camera, map_only(render::ColorMap::Gaussian));
    check_pixel(gauss, at(outer_equator), Hue::Red, "Gaussian, outer equator (K > 0)");
    check_pixel(gauss, at(inner_wall), Hue::Blue, "Gaussian, inner wall (K < 0)");

    const auto principal = test::render(torus, fields, 0.4f, camera, map_only(render::ColorMap::Principal));
    test::maybe_save(principal, "torus_principal");
    check_pixel(principal, at(outer_equator), Hue::Blue, "principal, outer equator (convex)");
    check_pixel(principal, at(inner_wall), Hue::Green, "principal, inner wall (saddle)");

    const auto dcurv = test::render(torus, fields, 0.4f, camera, map_only(render::ColorMap::DCurv));
    test::maybe_save(dcurv, "torus_dcurv");
    check_pixel(dcurv, at(outer_equator), Hue::White, "|C|, outer equator (|C| = 0)");
    check_pixel(dcurv, at(tube_top), Hue::Orange, "|C|, top of the tube (|C| = 0.6 of its range)");

    SECTION("the colour bar shows both ends of the map") {
        auto s = map_only(render::ColorMap::K2);
        s.colorbar = true;
        const auto image = test::render(torus, fields, 0.4f, camera, s);
        test::maybe_save(image, "torus_colorbar");
        // The bar: right edge, half the height, centred vertically.
        int left = image.width, right = 0;
        for (int x = 0; x < image.width; ++x)
            if (has_hue(image.at(x, 128 - 40), Hue::Red)) left = std::min(left, x), right = std::max(right, x);
        REQUIRE(left < right);
        CHECK(left > image.width * 3 / 4);  // only the bar, at the right
        const int x = (left + right) / 2;
        check_pixel(image, {x, 128 - 60}, Hue::Red, "top of the bar (high values)");
        check_pixel(image, {x, 128 + 60}, Hue::Blue, "bottom of the bar (low values)");
    }
}

TEST_CASE("Shadings hemisphere, toon-bw and gooch: lit towards the light, as their names say", "[render][shading]") {
    // A unit sphere seen from +z with the light towards the viewer: n.l = 1 at
    // the centre of the picture and 0 at the outline.
    const Mesh sphere = make_icosphere(1.0f, 5);
    const SurfaceFields exact = test::sphere_fields(sphere, 1.0f);
    const render::Camera camera = render::Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30);
    const render::BoundingSphere bounds = render::bounding_sphere(sphere);
    auto shaded = [&](render::Shading shading, glm::vec3 light = {0, 0, 1}) {
        render::RenderSettings s = test::lines_only(render::LineSelection{false, false, false, false});
        s.shading = shading;
        s.light_dir = light;
        return test::render(sphere, exact, 1.0f, camera, s, 128, 128);
    };
    // Points at n.l = 1 (centre), 0.7 and about 0.15 (near the outline).
    auto at = [&](const render::Image& im, float nl) {
        const glm::vec2 p = test::project(camera, bounds, {std::sqrt(1 - nl * nl), 0, nl}, 128, 128);
        return im.at(int(p.x), int(p.y));
    };
    const render::Image hemi = shaded(render::Shading::Hemisphere);
    CHECK(at(hemi, 1.0f).r > at(hemi, 0.7f).r);
    CHECK(at(hemi, 0.7f).r > at(hemi, 0.15f).r);
    CHECK(at(hemi, 0.15f).r > 80);  // the sky lights the far side too
    const render::Image bw = shaded(render::Shading::ToonBW);
    CHECK(at(bw, 1.0f).r == 255);
    CHECK(at(bw, 0.15f).r < 100);
    std::set<int> tones;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) tones.insert(bw.at(x, y).r);
    CHECK(tones.size() <= 3);  // two tones (and the white paper, the same as the lit tone)
    // Gooch, lit from the right (+x): warm on the right, cool on the left.
    const render::Image gooch = shaded(render::Shading::Gooch, {1, 0, 0});
    const glm::vec2 right = test::project(camera, bounds, {0.9f, 0, 0.43f}, 128, 128);
    const glm::vec2 left = test::project(camera, bounds, {-0.9f, 0, 0.43f}, 128, 128);
    const render::Rgba warm = gooch.at(int(right.x), int(right.y)), cool = gooch.at(int(left.x), int(left.y));
    CHECK(warm.r > warm.b);
    CHECK(cool.b > cool.r);
}

TEST_CASE("The light is fixed to the camera by default, to the model with light_on_model", "[render][shading]") {
    const Mesh sphere = make_icosphere(1.0f, 5);
    const SurfaceFields exact = test::sphere_fields(sphere, 1.0f);
    // The camera on +x looking at the sphere; the light along +x.
    const render::Camera camera = render::Camera::look_at({5, 0, 0}, {0, 0, 0}, {0, 1, 0}, 30);
    const render::BoundingSphere bounds = render::bounding_sphere(sphere);
    render::RenderSettings s = test::lines_only(render::LineSelection{false, false, false, false});
    s.shading = render::Shading::Lambert;
    s.light_dir = {1, 0, 0};
    const glm::vec2 centre = test::project(camera, bounds, {1, 0, 0}, 128, 128);              // n = +x
    const glm::vec2 right = test::project(camera, bounds, {0.2f, 0, -0.98f}, 128, 128);       // n about -z: image right
    // Camera frame: +x is the image's right: the right side is lit, the centre half.
    const render::Image cam = test::render(sphere, exact, 1.0f, camera, s, 128, 128);
    CHECK(cam.at(int(right.x), int(right.y)).r > cam.at(int(centre.x), int(centre.y)).r);
    // Model frame: +x of the model points at the camera: the centre is lit most.
    s.light_on_model = true;
    const render::Image model = test::render(sphere, exact, 1.0f, camera, s, 128, 128);
    CHECK(model.at(int(centre.x), int(centre.y)).r == 255);
    CHECK(model.at(int(centre.x), int(centre.y)).r > model.at(int(right.x), int(right.y)).r);
}

TEST_CASE("Vector glyphs: normals stick out of a sphere's outline, tangents stay within a stroke of it, "
          "the view direction is a point",
          "[render][vectors]") {
    const float R = 1.0f;
    const Mesh sphere = make_icosphere(R, 4);
    const SurfaceFields exact = test::sphere_fields(sphere, R);
    const render::Camera camera = render::Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30);
    const render::BoundingSphere bounds = render::bounding_sphere(sphere);
    // The outline's radius in pixels: the sphere's tangent cone from the eye.
    const glm::vec2 centre = test::project(camera, bounds, {0, 0, 0}, 256, 256);
    const float tangent_z = R * R / 5.0f, tangent_r = std::sqrt(R * R - tangent_z * tangent_z);
    const float outline = glm::length(test::project(camera, bounds, {tangent_r, 0, tangent_z}, 256, 256) - centre);
    auto draw = [&](int vectors) {
        render::RenderSettings s = test::lines_only(render::LineSelection{false, false, false, false});
        s.vectors = vectors;
        return test::render(sphere, exact, R, camera, s, 256, 256);
    };
    auto ink_beyond = [&](const render::Image& im, float radius) {
        size_t n = 0;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x)
                n += test::is_ink(im.at(x, y)) && glm::length(glm::vec2(x + 0.5f, y + 0.5f) - centre) > radius;
        return n;
    };
    const render::Image normals = draw(render::kGlyphNormal), tangents = draw(render::kGlyphPrincipal1),
                        view = draw(render::kGlyphView);
    INFO("outline radius " << outline << " px; normal ink " << test::count_ink(normals) << ", beyond the outline "
                           << ink_beyond(normals, outline + 2) << "; tangent ink " << test::count_ink(tangents)
                           << ", beyond " << ink_beyond(tangents, outline + 3));
    CHECK(ink_beyond(normals, outline + 2) > 100);
    CHECK(test::count_ink(tangents) > 500);
    // A tangent stroke is centred on its vertex (10 px each way, 2 px wide):
    // it never reaches further than that past the outline.
    CHECK(ink_beyond(tangents, outline + 12) == 0);
    CHECK(test::count_ink(view) == 0);
}

TEST_CASE("k1 and k2 maps differ where k1 != k2: a torus's inner wall is red in k1 and blue in k2",
          "[render][colormap]") {
    // Inner wall (cos v = -1): k1 = 1/r = 2.5 > 0, k2 = -1/(R - r) = -1.67 < 0.
    // A swap of k1 and k2 (or either map showing the other) fails; on a
    // sphere, where k1 = k2, it would not.
    const Mesh torus = make_torus(1.0f, 0.4f, 120, 48);
    const SurfaceFields fields = test::torus_fields(torus, 1.0f, 0.4f);
    const auto camera = render::Camera::look_at({0, -2.8f, 1.6f}, {0, 0, 0}, {0, 0, 1}, 40.0f);
    const render::BoundingSphere bounds = render::bounding_sphere(torus);
    const glm::vec2 inner_wall = test::project(camera, bounds, {0, 0.6f, 0}, 256, 256);
    const glm::vec2 outer_equator = test::project(camera, bounds, {0, -1.4f, 0}, 256, 256);
    const auto k1 = test::render(torus, fields, 0.4f, camera, map_only(render::ColorMap::K1));
    const auto k2 = test::render(torus, fields, 0.4f, camera, map_only(render::ColorMap::K2));
    check_pixel(k1, inner_wall, Hue::Red, "k1, inner wall (k1 = 1/r > 0)");
    check_pixel(k2, inner_wall, Hue::Blue, "k2, inner wall (k2 < 0)");
    check_pixel(k1, outer_equator, Hue::Red, "k1, outer equator (k1 = 1/r)");
    check_pixel(k2, outer_equator, Hue::Red, "k2, outer equator (k2 = 1/(R + r) > 0)");
}

TEST_CASE("Vector glyphs principal2 and asymptotic: along the second direction, and only where K < 0",
          "[render][vectors]") {
    // A coarse torus seen from above: at vertex (i, j) = (0, 2), v = 72
    // degrees, d1 runs along the tube, in the xz plane (along x on screen),
    // and d2 along the big circle (along y on screen). Neighbouring vertices
    // are more than 18 px away, so the strokes there are that vertex's own.
    // Asymptotic directions exist only where K < 0, the inner half (rho < R);
    // no vertex has v = 90 degrees (K = 0 up to rounding).
    const float R = 1.0f, r = 0.4f;
    const Mesh torus = make_torus(R, r, 16, 10);
    const SurfaceFields exact = test::torus_fields(torus, R, r);
    const render::Camera camera = render::Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30);
    const render::BoundingSphere bounds = render::bounding_sphere(torus);
    auto draw = [&](int vectors) {
        render::RenderSettings s = test::lines_only(render::LineSelection{false, false, false, false});
        s.vectors = vectors;
        return test::render(torus, exact, r, camera, s, 256, 256);
    };
    const glm::vec2 top = test::project(camera, bounds, torus.positions[2], 256, 256);
    auto ink_at = [](const render::Image& im, glm::vec2 p) { return test::is_ink(im.at(int(p.x), int(p.y))); };
    const render::Image first = draw(render::kGlyphPrincipal1), second = draw(render::kGlyphPrincipal2);
    for (const float o : {-5.0f, 5.0f}) {
        INFO("offset " << o << " px from the vertex at " << top.x << ", " << top.y);
        CHECK(ink_at(first, top + glm::vec2(o, 0)));
        CHECK_FALSE(ink_at(first, top + glm::vec2(0, o)));
        CHECK(ink_at(second, top + glm::vec2(0, o)));
        CHECK_FALSE(ink_at(second, top + glm::vec2(o, 0)));
    }
    const render::Image asymptotic = draw(render::kGlyphAsymptotic);
    const glm::vec2 centre = test::project(camera, bounds, {0, 0, 0}, 256, 256);
    const float inner_radius = glm::length(test::project(camera, bounds, {R, 0, r}, 256, 256) - centre);  // rho = R
    size_t ink = 0, outside = 0;
    for (int y = 0; y < asymptotic.height; ++y)
        for (int x = 0; x < asymptotic.width; ++x) {
            if (!test::is_ink(asymptotic.at(x, y))) continue;
            ++ink;
            outside += glm::length(glm::vec2(x + 0.5f, y + 0.5f) - centre) > inner_radius + 2;
        }
    INFO("asymptotic glyph ink " << ink << ", outside the inner half " << outside << " (radius " << inner_radius
                                 << " px)");
    CHECK(ink > 200);
    CHECK(outside == 0);
}
