#include "render/camera/orbit_camera.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>

namespace kappa::render {

namespace {

float fov_y(glm::vec2 viewport) { return glm::radians(rtsc_fov_y_deg(int(viewport.x), int(viewport.y))); }

// Camera-space direction of the ray through a pixel.
glm::vec3 pixel_ray(glm::vec2 pixel, glm::vec2 viewport) {
    const float t = std::tan(0.5f * fov_y(viewport));
    const float x = (2.0f * pixel.x / viewport.x - 1.0f) * t * viewport.x / viewport.y;
    const float y = (1.0f - 2.0f * pixel.y / viewport.y) * t;
    return glm::normalize(glm::vec3(x, y, -1));
}

// Gram-Schmidt on the rotation part, restoring the matrix's uniform scale, so
// that thousands of small rotations accumulate neither shear nor growth.
glm::mat4 reorthonormalize(const glm::mat4& m, float scale) {
    glm::vec3 x = glm::normalize(glm::vec3(m[0]));
    glm::vec3 y = glm::vec3(m[1]);
    y = glm::normalize(y - glm::dot(y, x) * x);
    const glm::vec3 z = glm::cross(x, y);
    glm::mat4 r = m;
    r[0] = glm::vec4(scale * x, 0);
    r[1] = glm::vec4(scale * y, 0);
    r[2] = glm::vec4(scale * z, 0);
    return r;
}

}  // namespace

void OrbitCamera::reset(const BoundingSphere& bounds, glm::vec2 viewport, glm::vec3 direction, glm::vec3 up) {
    view_ = Camera::framing(bounds, rtsc_fov_y_deg(int(viewport.x), int(viewport.y)), viewport.x / viewport.y,
                            direction, up)
                .view;
    pivot_ = bounds.center;
    scale_ = 1;
}

void OrbitCamera::fit(const BoundingSphere& bounds, glm::vec2 viewport) {
    const float half_y = 0.5f * fov_y(viewport);
    const float half_x = std::atan(std::tan(half_y) * viewport.x / viewport.y);
    const float distance = bounds.radius / std::sin(std::min(half_x, half_y));
    // Keep the orientation (without scale), put the centre straight ahead.
    const glm::mat4 rotation = reorthonormalize(glm::mat4(glm::mat3(view_)), 1.0f);
    view_ = glm::translate(glm::mat4(1), glm::vec3(0, 0, -distance)) * rotation *
            glm::translate(glm::mat4(1), -bounds.center);
    pivot_ = bounds.center;
    scale_ = 1;
}

void OrbitCamera::set_view(const glm::mat4& view) {
    view_ = view;
    scale_ = glm::length(glm::vec3(view[0]));
}

glm::vec3 OrbitCamera::arcball_point(glm::vec2 pixel, glm::vec2 viewport) {
    const float radius = 0.5f * std::min(viewport.x, viewport.y);
    glm::vec2 p((pixel.x - 0.5f * viewport.x) / radius, (0.5f * viewport.y - pixel.y) / radius);
    const float r2 = glm::dot(p, p);
    if (r2 >= 1.0f) return glm::vec3(p / std::sqrt(r2), 0.0f);
    return glm::vec3(p, std::sqrt(1.0f - r2));
}

void OrbitCamera::apply_in_camera(const glm::mat4& m) { view_ = m * view_; }

float OrbitCamera::pivot_depth() const { return std::max(-(view_ * glm::vec4(pivot_, 1)).z, 1e-6f); }

void OrbitCamera::orbit(glm::vec2 from, glm::vec2 to, glm::vec2 viewport) {
    const glm::vec3 a = arcball_point(from, viewport), b = arcball_point(to, viewport);
    const glm::vec3 axis = glm::cross(a, b);
    const float sin_angle = glm::length(axis);
    if (sin_angle < 1e-7f) return;
    // The arc between the two points: the grabbed point of the sphere
    // follows the cursor (a drag from the centre to the rim turns 90 degrees).
    const float angle = std::atan2(sin_angle, glm::dot(a, b));
    const glm::vec3 center = glm::vec3(view_ * glm::vec4(pivot_, 1));
    const glm::mat4 turn = glm::translate(glm::mat4(1), center) * glm::rotate(glm::mat4(1), angle, axis / sin_angle) *
                           glm::translate(glm::mat4(1), -center);
    apply_in_camera(turn);
    view_ = reorthonormalize(view_, scale_);
}

void OrbitCamera::pan(glm::vec2 from, glm::vec2 to, glm::vec2 viewport) {
    // World units per pixel at the pivot's depth.
    const float per_pixel = 2.0f * pivot_depth() * std::tan(0.5f * fov_y(viewport)) / viewport.y;
    const glm::vec2 d = (to - from) * per_pixel;
    apply_in_camera(glm::translate(glm::mat4(1), glm::vec3(d.x, -d.y, 0)));
}

void OrbitCamera::zoom(float steps, glm::vec2 cursor, glm::vec2 viewport) {
    // Each click brings the camera 15% closer to the pivot's depth along the
    // ray under the cursor; the point there stays under the cursor.
    const float depth = pivot_depth();
    const float factor = std::pow(0.85f, steps);
    const glm::vec3 ray = pixel_ray(cursor, viewport);
    const float travel = depth * (1.0f - factor) / -ray.z;  // along the ray, to depth * factor
    apply_in_camera(glm::translate(glm::mat4(1), -travel * ray));
}

Camera OrbitCamera::camera(glm::vec2 viewport) const {
    Camera c;
    c.view = view_;
    c.fov_y_deg = rtsc_fov_y_deg(int(viewport.x), int(viewport.y));
    return c;
}

}  // namespace kappa::render
