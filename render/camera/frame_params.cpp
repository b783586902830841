#include "render/camera/frame_params.h"

#include "render/render_settings.h"

#include <glm/geometric.hpp>

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

glm::vec3 camera_light_direction(const RenderSettings& settings, const FrameParams& frame) {
    const glm::vec3 l = unit_light_direction(settings);
    if (!settings.light_on_model) return l;
    const glm::vec3 c = frame.normal_matrix * l;
    const float len = glm::length(c);
    return len > 0 ? c / len : glm::vec3(0, 0, 1);
}

}  // namespace kappa::render
