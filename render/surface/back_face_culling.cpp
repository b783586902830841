#include "render/surface/back_face_culling.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace kappa::render {

BackFaceCulling back_face_culling(const BackFaceVisibility& visibility, const BoundingSphere& bounds,
                                  const MeshClusters& clusters, const FrameParams& frame) {
    BackFaceCulling out;
    if (!visibility.cullable || !(glm::distance(frame.eye, bounds.center) > bounds.radius * 1.001f)) return out;
    const int width = int(frame.viewport.x), height = int(frame.viewport.y);
    double covered = 0;  // by the holes' rectangles (overlaps counted twice: only a guide)
    for (const std::vector<glm::vec3>& hole : visibility.holes) {
        glm::vec2 lo(1e30f), hi(-1e30f);
        bool behind = false;
        for (const glm::vec3& p : hole) {
            const glm::vec4 c = frame.mvp * glm::vec4(p, 1.0f);
            if (!(c.w > 0.0f)) {
                behind = true;
                break;
            }
            const glm::vec2 window = (glm::vec2(c) / c.w * 0.5f + 0.5f) * frame.viewport;
            lo = glm::min(lo, window), hi = glm::max(hi, window);
        }
        if (behind || !std::isfinite(lo.x + lo.y + hi.x + hi.y)) lo = glm::vec2(0), hi = frame.viewport;
        lo = glm::clamp(lo, glm::vec2(-2.0f), frame.viewport + 2.0f);  // in range for int
        hi = glm::clamp(hi, glm::vec2(-2.0f), frame.viewport + 2.0f);
        // Whole pixels, one more on each side: any sample inside the hole's hull is inside.
        const int x0 = std::max(0, int(std::floor(lo.x)) - 1), y0 = std::max(0, int(std::floor(lo.y)) - 1);
        const int x1 = std::min(width, int(std::ceil(hi.x)) + 1), y1 = std::min(height, int(std::ceil(hi.y)) + 1);
        if (x1 <= x0 || y1 <= y0) continue;  // outside the image
        out.hole_rects.push_back({x0, y0, x1 - x0, y1 - y0});
        covered += double(x1 - x0) * double(y1 - y0);
    }
    if (covered > 0.5 * double(width) * double(height)) return BackFaceCulling{};
    out.cull = true;
    out.mirrored = glm::determinant(glm::mat3(frame.model_view)) < 0.0f;
    if (out.hole_rects.empty()) return out;
    glm::ivec2 lo(width, height), hi(0);
    for (const glm::ivec4& r : out.hole_rects)
        lo = glm::min(lo, glm::ivec2(r.x, r.y)), hi = glm::max(hi, glm::ivec2(r.x + r.z, r.y + r.w));
    out.holes = {lo, hi - lo};
    out.back_runs = back_facing_runs_in(clusters, frame, out.hole_rects);
    return out;
}

}  // namespace kappa::render
