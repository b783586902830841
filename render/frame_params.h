// Per-frame camera data shared by the render passes.
#pragma once

#include "render/camera.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace kappa::render {

struct FrameParams {
    glm::mat4 model_view{1}, projection{1}, mvp{1};
    glm::mat3 normal_matrix{1};  // inverse transpose of the model-view's 3x3
    glm::vec3 eye{0};            // model coordinates
    glm::vec2 viewport{1, 1};    // pixels

    static FrameParams make(const Camera& camera, const BoundingSphere& bounds, int width, int height);
};

}  // namespace kappa::render
