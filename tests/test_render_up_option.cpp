// --up and --view about it (app/render_options.h: make_camera): the default
// view and --view AZ,EL are taken about --up; without --up, --view stays
// about +y and the default view takes the shape's up axis.
#include "app/mesh_drawing.h"
#include "app/render_options.h"
#include "geometry/mesh/primitives.h"
#include "geometry/scale/scale_space.h"
#include "geometry/view/default_view.h"
#include "render/camera/camera.h"
#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "test_render_fixtures.h"
#include "test_shapes.h"
#include "test_support.h"
#include "test_upright_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

using namespace kappa;

namespace {

// Direction from the bounds' centre to the eye, and the camera's up (image
// y) in model coordinates.
struct Seen {
    glm::vec3 eye, up;
};

Seen seen(const render::Camera& c, const render::BoundingSphere& b) {
    const glm::mat4 to_model = glm::inverse(c.view);
    return {glm::normalize(c.eye() - b.center), glm::normalize(glm::vec3(to_model * glm::vec4(0, 1, 0, 0)))};
}

bool near(glm::vec3 a, glm::vec3 b, float tol = 1e-4f) { return glm::length(a - b) < tol; }

}  // namespace

TEST_CASE("kappa render: --view AZ,EL is taken about --up, and about +y without it", "[render][camera]") {
    const Mesh bust = test::bust_z_up();
    const render::BoundingSphere b = render::bounding_sphere(bust);
    app::CameraOptions o;
    o.view = ViewAngles{30, 20};
    // Without --up: about +y, y up in the image (as before --up took part).
    glm::vec3 axis(0);
    Seen s = seen(app::make_camera(o, bust, b, {400, 300}, nullptr, {}, &axis), b);
    CHECK(near(axis, {0, 1, 0}));
    CHECK(near(s.eye, view_direction({30, 20})));
    CHECK(glm::dot(s.up, glm::vec3(0, 1, 0)) > 0.9f);
    // With --up 0,0,1: azimuth 0 from -y, 90 from +x; z up in the image.
    o.has_up = true, o.up = {0, 0, 2};
    s = seen(app::make_camera(o, bust, b, {400, 300}, nullptr, {}, &axis), b);
    CHECK(near(axis, {0, 0, 1}));
    CHECK(near(s.eye, view_direction({30, 20}, {0, 0, 1})));
    CHECK(s.eye.y < 0);
    CHECK(s.eye.x > 0);
    CHECK(glm::dot(s.up, glm::vec3(0, 0, 1)) == Approx(std::cos(glm::radians(20.0f))).margin(1e-4));
    // Straight down --up: a top view, no throw, the frame's front down the image.
    o.view = ViewAngles{0, 90};
    s = seen(app::make_camera(o, bust, b, {400, 300}), b);
    CHECK(near(s.eye, {0, 0, 1}));
    CHECK(std::isfinite(s.up.x + s.up.y + s.up.z));
}

TEST_CASE("The default view stands on the shape's up axis, or on --up", "[render][camera]") {
    const Mesh bust = test::bust_z_up();
    const render::BoundingSphere b = render::bounding_sphere(bust);
    app::CameraOptions o;
    const DefaultView v = default_view(bust);
    REQUIRE(near(v.up, {0, 0, 1}));
    glm::vec3 axis(0);
    Seen s = seen(app::make_camera(o, bust, b, {400, 300}, nullptr, {}, &axis), b);
    CHECK(near(axis, {0, 0, 1}));  // the axis a turntable of this view turns about
    CHECK(near(s.eye, v.eye));
    CHECK(glm::dot(s.up, v.up) > 0.8f);                      // z up in the image
    CHECK(std::fabs(glm::dot(glm::cross(s.up, s.eye), v.up)) < 1e-4f);  // no roll: image x level
    // --up 0,1,0 overrides it: the view about y, as before up detection.
    o.has_up = true, o.up = {0, 1, 0};
    s = seen(app::make_camera(o, bust, b, {400, 300}, nullptr, {}, &axis), b);
    CHECK(near(axis, {0, 1, 0}));
    CHECK(near(s.eye, view_direction(choose_default_view(bust))));
    CHECK(glm::dot(s.up, glm::vec3(0, 1, 0)) > 0.8f);
    // --eye without --up: y up, as before.
    o.has_up = false, o.has_eye = true, o.eye = b.center + glm::vec3(0, -1, 0.2f);
    s = seen(app::make_camera(o, bust, b, {400, 300}), b);
    CHECK(glm::dot(s.up, glm::vec3(0, 1, 0)) > 0.1f);
}


TEST_CASE("A turntable of a z-up bust turns about its up axis, as kappa info reports it", "[render][cli][turntable]") {
    // The bust stands on a flat base at z = 0, so its default view stands on
    // +z (kappa info: "default view: eye X,Y,Z up X,Y,Z"). Frame i of
    // --turntable 4 must be that view turned by 90 i degrees about that up
    // (drawn with --view AZ,EL --up), not turned about +y (it would tumble).
    const Mesh bust = test::bust_z_up();
    const std::string dir = test::temp_dir(), mesh_path = dir + "/bust.off";
    test::write_off(mesh_path, bust);
    const auto info = test::run_command(std::string(KAPPA_EXE) + " info " + mesh_path + " --no-curvature");
    INFO(info.output);
    REQUIRE(info.exit_code == 0);
    glm::vec3 eye, up;
    const size_t at = info.output.find("default view:");
    REQUIRE(at != std::string::npos);
    REQUIRE(std::sscanf(info.output.c_str() + at, "default view: eye %f,%f,%f up %f,%f,%f", &eye.x, &eye.y, &eye.z,
                        &up.x, &up.y, &up.z) == 6);
    CHECK(up.z > 0.99f);
    const std::string common = " -q --size 200x200 --shading none --lines contours --msaa off";
    const auto r = test::run_command(test::kappa_render(mesh_path + common + " --turntable 4 -o " + dir + "/t.png"));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    // The default view's angles about that up (--view AZ,EL --up U draws the same camera).
    const float el = glm::degrees(std::asin(glm::clamp(glm::dot(eye, up), -1.0f, 1.0f)));
    float az = 0, best = 1e9f;
    for (float a = -180; a < 180; a += 0.05f) {
        const float miss = glm::length(view_direction({a, el}, up) - eye);
        if (miss < best) best = miss, az = a;
    }
    REQUIRE(best < 1e-3f);
    for (int i = 1; i < 4; ++i) {
        const std::string single = dir + "/v" + std::to_string(i) + ".png";
        REQUIRE(test::run_command(test::kappa_render(mesh_path + common + " --view " + std::to_string(az + 90.0f * i) +
                                                     "," + std::to_string(el) + " --up 0,0,1 -o " + single))
                    .exit_code == 0);
        const render::Image frame = render::read_png(dir + "/t-00" + std::to_string(i) + ".png");
        const render::Image expected = render::read_png(single);
        const double near = render::ink_within(frame, expected, 1.0f), back = render::ink_within(expected, frame, 1.0f);
        INFO("frame " << i << ": ink within 1 px of the turned view " << near << ", back " << back);
        CHECK(test::count_ink(frame) > 200);
        CHECK(near > 0.97);
        CHECK(back > 0.97);
    }
}

// The drawing's default view reads the scan denoised (MeshDrawing::view_surface) and says so: a
// noisy standing figure, whose soles are no longer flat, stands on its blunter end
// (geometry/view/default_view.h), with the detail pipeline's denoising and without detail.
TEST_CASE("kappa render: a noisy scan of a standing figure is drawn upright, with and without detail",
          "[render][camera]") {
    Mesh figure = test::figure_z_up();
    add_normal_noise(figure, 0.33f * mean_edge_length(figure), 1);
    for (float detail : {12.0f, 0.0f}) {
        render::RenderSettings settings;
        settings.detail = detail;
        app::MeshDrawing drawing(figure, settings, SmoothingOptions{});
        glm::vec3 axis(0);
        const Seen s = seen(app::make_camera(app::CameraOptions{}, drawing, {300, 300}, nullptr, &axis), drawing.bounds());
        INFO("detail " << detail << ": up " << axis.x << "," << axis.y << "," << axis.z);
        CHECK(near(axis, {0, 0, 1}));
        CHECK(s.up.z > 0.9f);
        CHECK(glm::dot(s.eye, axis) > 0);
    }
}
