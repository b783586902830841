// Per-frame camera data shared by the render passes.
#pragma once

#include "render/camera/camera.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace kappa::render {

struct RenderSettings;

struct FrameParams {
    glm::mat4 model_view{1}, projection{1}, mvp{1};
    glm::mat3 normal_matrix{1};  // inverse transpose of the model-view's 3x3
    glm::vec3 eye{0};            // model coordinates
    glm::vec2 viewport{1, 1};    // pixels

    static FrameParams make(const Camera& camera, const BoundingSphere& bounds, int width, int height);
};

// The unit direction towards the light in camera coordinates for this frame
// (RenderSettings::light_dir, given in camera or, light_on_model, in model
// coordinates).
glm::vec3 camera_light_direction(const RenderSettings& settings, const FrameParams& frame);

}  // namespace kappa::render
