// Interactive camera control for the viewer: a virtual trackball (Shoemake's
// arcball, Graphics Interface 1992) that rotates about a pivot, panning in
// the image plane, and zooming toward the point under the cursor. The state
// is the model-view matrix itself, changed by rotations and translations in
// camera coordinates, so there are no Euler angles to flip or lock, and any
// matrix read from a .xf file can be continued from.
//
// Pixel coordinates: x right, y down, origin at the top-left of the view
// (as GLFW reports the cursor), in the same units as `viewport`.
#pragma once

#include "render/camera/camera.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace kappa::render {

class OrbitCamera {
public:
    // Frames `bounds` from `direction` (centre towards the eye; Camera::framing)
    // and orbits about its centre.
    // up: the model's up axis, up in the image (geometry/view/default_view.h).
    void reset(const BoundingSphere& bounds, glm::vec2 viewport, glm::vec3 direction = glm::vec3(0, 0, 1),
               glm::vec3 up = glm::vec3(0, 1, 0));
    // Frames `bounds` again from the current viewing direction.
    void fit(const BoundingSphere& bounds, glm::vec2 viewport);
    // Continues from a given model-view matrix (e.g. a .xf file).
    void set_view(const glm::mat4& view);
    // The point orbits turn about (model coordinates).
    void set_pivot(glm::vec3 pivot) { pivot_ = pivot; }

    // Trackball rotation for a drag from `from` to `to`: the point of the
    // arcball sphere under `from` is carried to the one under `to`.
    void orbit(glm::vec2 from, glm::vec2 to, glm::vec2 viewport);
    // Moves the model with the cursor (at the pivot's depth).
    void pan(glm::vec2 from, glm::vec2 to, glm::vec2 viewport);
    // Moves toward the point under `cursor` by `steps` wheel clicks (> 0:
    // closer); that point stays under the cursor.
    void zoom(float steps, glm::vec2 cursor, glm::vec2 viewport);

    // The camera for a view of this size; the field of view is rtsc's
    // default (rtsc_fov_y_deg) so that a saved .xf renders identically with
    // `kappa render --xf FILE --size WxH`.
    Camera camera(glm::vec2 viewport) const;
    const glm::mat4& view() const { return view_; }
    glm::vec3 pivot() const { return pivot_; }

    // Unit vector on the arcball sphere under a pixel (the sphere fills the
    // smaller side of the view; outside it, the nearest point of its rim).
    static glm::vec3 arcball_point(glm::vec2 pixel, glm::vec2 viewport);

private:
    // Applies a transform given in camera coordinates: view <- m * view.
    void apply_in_camera(const glm::mat4& m);
    float pivot_depth() const;  // distance of the pivot in front of the camera

    glm::mat4 view_{1};
    glm::vec3 pivot_{0};  // model coordinates
    float scale_ = 1;     // uniform scale of the model-view (1 unless a .xf file had one)
};

}  // namespace kappa::render
