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

namespace {

// The largest value of sign * Dw kr * fs^2 on the front-facing zero set of kr
// seen from `eye`, from the fields by the formulas of conventions.md
// (written out here, not taken from geometry/lines): kr's zeros where it
// changes sign along an edge, Dw kr linear along the edge as the lines are.
float largest_dwkr_on_kr_zeros(const Mesh& mesh, const SurfaceFields& f, glm::vec3 eye, float fs, float sign) {
    const size_t n = mesh.vertex_count();
    std::vector<float> kr(n), dwkr(n), ndotv(n);
    for (size_t i = 0; i < n; ++i) {
        const glm::vec3 v = glm::normalize(eye - mesh.positions[i]);
        const float u = glm::dot(v, f.d1[i]), t = glm::dot(v, f.d2[i]);
        const float sin2 = u * u + t * t, sin_theta = std::sqrt(sin2);
        ndotv[i] = glm::dot(f.normals[i], v);
        kr[i] = f.k1[i] * u * u + f.k2[i] * t * t;  // kr sin^2: the same zeros
        const float w1 = u / sin_theta, w2 = t / sin_theta;
        const glm::vec4 C = f.dcurv[i];
        const float cwww = C.x * w1 * w1 * w1 + 3 * C.y * w1 * w1 * w2 + 3 * C.z * w1 * w2 * w2 + C.w * w2 * w2 * w2;
        const float tau = (f.k2[i] - f.k1[i]) * w1 * w2;
        dwkr[i] = cwww - 2 * tau * tau * ndotv[i] / sin_theta;
    }
    float largest = -1e30f;
    for (const Face& face : mesh.faces)
        for (int e = 0; e < 3; ++e) {
            const uint32_t i = face[e], j = face[(e + 1) % 3];
            if ((kr[i] > 0) == (kr[j] > 0) || ndotv[i] <= 0 || ndotv[j] <= 0) continue;
            const float s = kr[i] / (kr[i] - kr[j]);
            largest = std::max(largest, sign * (dwkr[i] + s * (dwkr[j] - dwkr[i])) * fs * fs);
        }
    return largest;
}

}  // namespace

TEST_CASE("Thresholds --sc-threshold and --sh-threshold: lines only where sign * Dw kr fs^2 exceeds them, on a torus",
          "[render][suggestive][thresholds]") {
    // Exact torus fields, fs = 0.4, no fading: a threshold a little above the
    // largest value of the quantity on the line leaves no ink at all, one a
    // little below it leaves some. An ignored threshold, or one applied at
    // another scale (fs instead of fs^2, say), fails one or the other.
    const Torus torus;
    const float fs = 0.4f;
    const glm::vec3 eye = glm::vec3(glm::inverse(kTorusView.view)[3]);
    struct Kind {
        const char* name;
        bool render::LineSelection::*flag;
        float render::RenderSettings::*threshold;
        float sign;
    };
    for (const Kind& k : {Kind{"suggestive contours", &render::LineSelection::suggestive,
                               &render::RenderSettings::sc_threshold, 1.0f},
                          Kind{"suggestive highlights", &render::LineSelection::suggestive_highlights,
                               &render::RenderSettings::sh_threshold, -1.0f}}) {
        const float largest = largest_dwkr_on_kr_zeros(torus.mesh, torus.fields, eye, fs, k.sign);
        auto settings = test::lines_only({false, false, false});
        settings.lines.creases = false;
        settings.lines.*k.flag = true;
        settings.fade = false;
        settings.detail = 0;
        auto ink_at = [&](float s) {
            settings.*k.threshold = s;
            return test::count_ink(test::render(torus.mesh, torus.fields, fs, kTorusView, settings));
        };
        // Measured ink at 0, 0.75 and 1.15 of the largest value: suggestive
        // contours 854, 51, 0; highlights 235, 106, 0 (2026-11-26).
        const size_t below = ink_at(0.75f * largest), above = ink_at(1.15f * largest), zero = ink_at(0);
        INFO(k.name << ": largest value on the line " << largest << "; ink at threshold 0: " << zero
                    << ", 0.75 of it: " << below << ", 1.15 of it: " << above);
        REQUIRE(largest > 0.01f);
        CHECK(below > 20);
        CHECK(below < zero);  // and the threshold removed some on the way
        CHECK(above == 0);
    }
}

TEST_CASE("Thresholds --rv-threshold and --ph-threshold: no ridge above the largest |kmax| fs, none of those lines above their "
          "bound, and a visible cut below",
          "[render][curvature-lines][thresholds]") {
    // An ellipsoid with estimated fields: ridges where |kmax| fs > S (the
    // largest |kmax| at the tip of its longest axis, a ridge point);
    // principal highlights where (kmax^2 - kmin^2) n.v fs^2 > S, at most
    // max (kmax^2 - kmin^2) fs^2 since n.v <= 1.
    const Mesh blob = make_ellipsoid(1.0f, 0.6f, 0.8f, 5);
    const SurfaceFields fields = compute_surface_fields(blob);
    const float fs = feature_size(blob, fields);
    const auto camera = render::Camera::look_at({3.0f, 1.0f, 1.5f}, {0, 0, 0}, {0, 0, 1}, 35.0f);
    float kmax_fs = 0, ph_bound = 0;
    for (size_t i = 0; i < fields.size(); ++i) {
        const float big = std::max(std::fabs(fields.k1[i]), std::fabs(fields.k2[i]));
        const float small = std::min(std::fabs(fields.k1[i]), std::fabs(fields.k2[i]));
        kmax_fs = std::max(kmax_fs, big * fs);
        ph_bound = std::max(ph_bound, (big * big - small * small) * fs * fs);
    }
    auto settings = test::lines_only({false, false, false});
    settings.lines.creases = false;
    settings.fade = false;
    settings.detail = 0;
    auto ink = [&](bool render::LineSelection::*flag, float render::RenderSettings::*threshold, float s) {
        auto t = settings;
        t.lines.*flag = true;
        t.*threshold = s;
        const auto image = test::render(blob, fields, fs, camera, t);
        return test::count_ink(image);
    };
    const size_t ridges_low = ink(&render::LineSelection::ridges, &render::RenderSettings::rv_threshold, 0.5f * kmax_fs);
    const size_t ridges_below =
        ink(&render::LineSelection::ridges, &render::RenderSettings::rv_threshold, 0.9f * kmax_fs);
    const size_t ridges_above =
        ink(&render::LineSelection::ridges, &render::RenderSettings::rv_threshold, 1.05f * kmax_fs);
    INFO("largest |kmax| fs " << kmax_fs << ": ridge ink at 0.5, 0.9 and 1.05 of it " << ridges_low << ", "
                              << ridges_below << ", " << ridges_above);
    CHECK(ridges_below > 10);
    CHECK(ridges_low > ridges_below + 50);
    CHECK(ridges_above == 0);
    const size_t ph_low = ink(&render::LineSelection::principal_highlights, &render::RenderSettings::ph_threshold, 0);
    const size_t ph_mid =
        ink(&render::LineSelection::principal_highlights, &render::RenderSettings::ph_threshold, 0.3f * ph_bound);
    const size_t ph_above =
        ink(&render::LineSelection::principal_highlights, &render::RenderSettings::ph_threshold, 1.05f * ph_bound);
    INFO("principal highlights: bound " << ph_bound << ", ink at 0, 0.3 and 1.05 of it " << ph_low << ", " << ph_mid
                                        << ", " << ph_above);
    CHECK(ph_low > 50);
    CHECK(ph_mid < ph_low * 3 / 4);
    CHECK(ph_above == 0);
}

TEST_CASE("Threshold --ar-threshold: a higher threshold visibly removes apparent ridges, a huge one all",
          "[render][thresholds]") {
    const Mesh blob = make_ellipsoid(1.0f, 0.6f, 0.8f, 5);
    const SurfaceFields fields = compute_surface_fields(blob);
    const float fs = feature_size(blob, fields);
    const auto camera = render::Camera::look_at({3.0f, 1.0f, 1.5f}, {0, 0, 0}, {0, 0, 1}, 35.0f);
    auto settings = test::lines_only({false, false, false});
    settings.lines.creases = false;
    settings.lines.apparent_ridges = true;
    settings.fade = false;
    settings.detail = 0;
    auto ink_at = [&](float s) {
        settings.ar_threshold = s;
        return test::count_ink(test::render(blob, fields, fs, camera, settings));
    };
    // Measured ink (2026-11-26): the same 1128 px from 0.5 to 10 (the
    // ellipsoid's apparent ridges are strong, near its outline), 337 at 50,
    // 12 at 300, none from 1000.
    const size_t low = ink_at(10.0f), mid = ink_at(50.0f), huge = ink_at(1e4f);
    INFO("apparent ridge ink at 10, 50 and 1e4: " << low << ", " << mid << ", " << huge);
    CHECK(low > 500);
    CHECK(mid < low * 3 / 4);
    CHECK(huge == 0);
}
