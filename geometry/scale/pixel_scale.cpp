#include "pixel_scale.h"

#include "geometry/parallel/parallel.h"

#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

std::vector<float> pixel_sizes(const Mesh& mesh, const glm::mat4& view, float fov_y_deg, int image_height) {
    const float per_depth = 2.0f * std::tan(0.5f * fov_y_deg * float(M_PI) / 180.0f) / float(std::max(image_height, 1));
    std::vector<float> out(mesh.vertex_count());
    // Row 2 of the view matrix gives the camera-space z of a point.
    const glm::vec4 row(view[0][2], view[1][2], view[2][2], view[3][2]);
    parallel_for(out.size(), [&](size_t v) {
        const glm::vec3& p = mesh.positions[v];
        const float depth = std::fabs(row.x * p.x + row.y * p.y + row.z * p.z + row.w);
        out[v] = std::max(depth * per_depth, 1e-30f);
    });
    return out;
}

}  // namespace kappa
