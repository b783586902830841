// How large a pixel is on the surface: for a perspective camera, one pixel
// at depth z along the view direction spans z * 2 tan(fov_y / 2) / height
// model units. Drawings choose the scale of their curvature fields from it
// (scale_space.h).
#pragma once

#include "geometry/mesh/mesh.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace kappa {

// Per vertex: the pixel size at the vertex's depth. view: model -> camera
// coordinates (camera at the origin looking down -z); fov_y_deg: vertical
// field of view; image_height in pixels. Vertices behind the camera get the
// size at their distance from the camera plane (never zero or negative).
std::vector<float> pixel_sizes(const Mesh& mesh, const glm::mat4& view, float fov_y_deg, int image_height);

}  // namespace kappa
