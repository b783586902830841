#include "render/frame_params.h"

#include <glm/matrix.hpp>

namespace kappa::render {

FrameParams FrameParams::make(const Camera& camera, const BoundingSphere& bounds, int width, int height) {
    FrameParams f;
    const float aspect = float(width) / float(height);
    f.model_view = camera.view;
    f.projection = camera.projection(bounds, aspect);
    f.mvp = f.projection * f.model_view;
    f.normal_matrix = glm::transpose(glm::inverse(glm::mat3(camera.view)));
    f.eye = camera.eye();
    f.viewport = glm::vec2(float(width), float(height));
    return f;
}

}  // namespace kappa::render
