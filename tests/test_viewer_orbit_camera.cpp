// The viewer's camera control (render/camera/orbit_camera.h): trackball rotation
// about the pivot without drift, flips or locks; panning that follows the
// cursor; zoom toward the point under the cursor; fit and reset.
#include <catch2/catch.hpp>

#include "render/camera/orbit_camera.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <cmath>
#include <random>

using namespace kappa;
using render::OrbitCamera;

namespace {

const glm::vec2 kViewport(640, 480);
const render::BoundingSphere kBounds{{0.5f, -0.25f, 2.0f}, 1.5f};

// Pixel (x right, y down) where a model point appears.
glm::vec2 project(const OrbitCamera& c, glm::vec3 p) {
    const render::Camera cam = c.camera(kViewport);
    const glm::vec4 clip = cam.projection(kBounds, kViewport.x / kViewport.y) * cam.view * glm::vec4(p, 1);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x + 1) * 0.5f * kViewport.x, (1 - ndc.y) * 0.5f * kViewport.y};
}

// Largest deviation of the view's 3x3 from a rotation.
float orthonormality_error(const glm::mat4& view) {
    const glm::mat3 r(view);
    const glm::mat3 e = glm::transpose(r) * r - glm::mat3(1);
    float m = std::abs(glm::determinant(r) - 1);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m = std::max(m, std::abs(e[i][j]));
    return m;
}

OrbitCamera framed() {
    OrbitCamera c;
    c.reset(kBounds, kViewport);
    return c;
}

}  // namespace

TEST_CASE("the arcball maps pixels onto the unit sphere, the centre to the front", "[viewer][camera]") {
    const glm::vec3 front = OrbitCamera::arcball_point(kViewport * 0.5f, kViewport);
    CHECK(glm::length(front - glm::vec3(0, 0, 1)) < 1e-6f);
    for (glm::vec2 p : {glm::vec2(0, 0), glm::vec2(600, 20), glm::vec2(320, 100), glm::vec2(-50, 900)})
        CHECK(glm::length(OrbitCamera::arcball_point(p, kViewport)) == Approx(1.0f).margin(1e-5));
    // Up on the screen is +y on the sphere.
    CHECK(OrbitCamera::arcball_point({320, 100}, kViewport).y > 0);
}

TEST_CASE("reset frames the bounding sphere from +z, centred", "[viewer][camera]") {
    const OrbitCamera c = framed();
    const glm::vec2 centre = project(c, kBounds.center);
    CHECK(centre.x == Approx(320).margin(0.01));
    CHECK(centre.y == Approx(240).margin(0.01));
    CHECK(c.camera(kViewport).eye().z > kBounds.center.z + kBounds.radius);
}

TEST_CASE("orbiting turns about the pivot, which stays put on screen", "[viewer][camera]") {
    OrbitCamera c = framed();
    const glm::vec3 eye_before = c.camera(kViewport).eye();
    c.orbit({320, 240}, {420, 240}, kViewport);  // to the right: the model turns about the screen's y axis
    const glm::vec3 eye_after = c.camera(kViewport).eye();
    CHECK(glm::distance(eye_after, kBounds.center) == Approx(glm::distance(eye_before, kBounds.center)).epsilon(1e-5));
    CHECK(eye_after.y == Approx(eye_before.y).margin(1e-4));  // horizontal drag: no tilt
    CHECK(eye_after.x < eye_before.x);  // the model turned right, so the camera went left around it
    const glm::vec2 pivot = project(c, kBounds.center);
    CHECK(pivot.x == Approx(320).margin(0.01));
    CHECK(pivot.y == Approx(240).margin(0.01));
}

TEST_CASE("the grabbed point of the trackball follows the cursor", "[viewer][camera]") {
    OrbitCamera c = framed();
    const glm::vec2 from(300, 200), to(360, 260);
    const glm::vec3 a = OrbitCamera::arcball_point(from, kViewport);
    const glm::mat3 before(c.view());
    c.orbit(from, to, kViewport);
    // The camera-space direction a, rotated with the model, lands on b.
    const glm::vec3 moved = glm::mat3(c.view()) * glm::transpose(before) * a;
    CHECK(glm::length(moved - OrbitCamera::arcball_point(to, kViewport)) < 1e-4f);
}

TEST_CASE("thousands of drags, over the poles too, never flip, lock or drift", "[viewer][camera]") {
    OrbitCamera c = framed();
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> px(0, 640), py(0, 480);
    for (int i = 0; i < 5000; ++i) c.orbit({px(rng), py(rng)}, {px(rng), py(rng)}, kViewport);
    CHECK(orthonormality_error(c.view()) < 1e-4f);
    const float distance = glm::distance(c.camera(kViewport).eye(), kBounds.center);

    // A vertical drag keeps turning smoothly past the poles (no gimbal lock):
    // 36 steps of 10 pixels near the centre each turn by the same angle.
    OrbitCamera v = framed();
    float previous = -1;
    for (int i = 0; i < 36; ++i) {
        const glm::mat3 before(v.view());
        v.orbit({320, 235}, {320, 245}, kViewport);
        const glm::mat3 step = glm::mat3(v.view()) * glm::transpose(before);
        const float angle = std::acos(std::min(1.0f, (step[0][0] + step[1][1] + step[2][2] - 1) / 2));
        CHECK(angle > 0.01f);
        if (previous > 0) CHECK(angle == Approx(previous).epsilon(1e-3));
        previous = angle;
    }
    CHECK(glm::distance(c.camera(kViewport).eye(), kBounds.center) == Approx(distance).epsilon(1e-4));
}

TEST_CASE("a drag and its reverse bring the view back", "[viewer][camera]") {
    OrbitCamera c = framed();
    const glm::mat4 start = c.view();
    c.orbit({200, 100}, {500, 400}, kViewport);
    c.orbit({500, 400}, {200, 100}, kViewport);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) CHECK(c.view()[i][j] == Approx(start[i][j]).margin(1e-4));
}

TEST_CASE("panning moves the pivot with the cursor", "[viewer][camera]") {
    OrbitCamera c = framed();
    c.pan({100, 100}, {160, 130}, kViewport);
    const glm::vec2 pivot = project(c, kBounds.center);
    CHECK(pivot.x == Approx(380).margin(0.05));
    CHECK(pivot.y == Approx(270).margin(0.05));
}

TEST_CASE("zooming moves toward the point under the cursor, which stays there", "[viewer][camera]") {
    OrbitCamera c = framed();
    const glm::vec2 cursor(500, 150);
    // The point under the cursor at the pivot's depth.
    const render::Camera cam = c.camera(kViewport);
    const glm::mat4 inv = glm::inverse(cam.projection(kBounds, kViewport.x / kViewport.y) * cam.view);
    const glm::vec4 pivot_clip = cam.projection(kBounds, kViewport.x / kViewport.y) * cam.view * glm::vec4(kBounds.center, 1);
    const float ndc_z = pivot_clip.z / pivot_clip.w;
    const glm::vec4 p = inv * glm::vec4(cursor.x / 320 - 1, 1 - cursor.y / 240, ndc_z, 1);
    const glm::vec3 target = glm::vec3(p) / p.w;

    const float before = glm::distance(c.camera(kViewport).eye(), target);
    c.zoom(3, cursor, kViewport);
    const float after = glm::distance(c.camera(kViewport).eye(), target);
    CHECK(after < 0.7f * before);
    const glm::vec2 seen = project(c, target);
    CHECK(seen.x == Approx(cursor.x).margin(0.05));
    CHECK(seen.y == Approx(cursor.y).margin(0.05));
    c.zoom(-3, cursor, kViewport);  // and back out
    CHECK(glm::distance(c.camera(kViewport).eye(), target) == Approx(before).epsilon(1e-4));
}

TEST_CASE("fit keeps the direction of view and frames the sphere again", "[viewer][camera]") {
    OrbitCamera c = framed();
    c.orbit({320, 240}, {400, 200}, kViewport);
    c.pan({0, 0}, {100, 50}, kViewport);
    c.zoom(5, {100, 100}, kViewport);
    const glm::mat3 rotation(c.view());
    c.fit(kBounds, kViewport);
    CHECK(glm::length(glm::mat3(c.view())[0] - rotation[0]) < 1e-4f);
    CHECK(glm::length(glm::mat3(c.view())[1] - rotation[1]) < 1e-4f);
    const glm::vec2 centre = project(c, kBounds.center);
    CHECK(centre.x == Approx(320).margin(0.01));
    CHECK(centre.y == Approx(240).margin(0.01));
    const OrbitCamera fresh = framed();
    CHECK(glm::distance(c.camera(kViewport).eye(), kBounds.center) ==
          Approx(glm::distance(fresh.camera(kViewport).eye(), kBounds.center)).epsilon(1e-4));
}

TEST_CASE("orbiting continues from a scaled .xf matrix without losing its scale", "[viewer][camera]") {
    OrbitCamera c = framed();
    glm::mat4 view = glm::scale(c.view(), glm::vec3(2.5f));
    c.set_view(view);
    c.set_pivot(kBounds.center);
    for (int i = 0; i < 100; ++i) c.orbit({300, 200}, {320, 230}, kViewport);
    CHECK(glm::length(glm::vec3(c.view()[0])) == Approx(2.5f).epsilon(1e-4));
    CHECK(glm::length(glm::vec3(c.view()[2])) == Approx(2.5f).epsilon(1e-4));
}
