// --up and --view about it (app/render_options.h: make_camera): the default
// view and --view AZ,EL are taken about --up; without --up, --view stays
// about +y and the default view takes the shape's up axis.
#include "app/render_options.h"
#include "geometry/view/default_view.h"
#include "render/camera/camera.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "test_upright_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>

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
