#include "render/lines/screen_merge.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa::render {

namespace {

struct ScreenPoint {
    glm::vec2 xy;  // window pixels
    float z;       // window depth
    bool in_front;  // w > 0
};

}  // namespace

float fast_atan2(float y, float x) {
    const float ax = std::fabs(x), ay = std::fabs(y);
    const float lo = std::min(ax, ay), hi = std::max(ax, ay);
    const float a = hi > 0 ? lo / hi : 0.0f, s = a * a;
    // Abramowitz and Stegun 4.4.49: |error| <= 1e-5 on [0, 1].
    float r = a * (0.9998660f + s * (-0.3302995f + s * (0.1801410f + s * (-0.0851330f + s * 0.0208351f))));
    if (ay > ax) r = 1.57079637f - r;
    if (x < 0) r = 3.14159274f - r;
    return y < 0 ? -r : r;
}

void merge_on_screen(const Polyline& line, const ScreenMergeParams& p, std::vector<LineSegment>& out) {
    const size_t n = line.points.size();
    if (n < 2) return;
    std::vector<ScreenPoint> s(n);
    for (size_t i = 0; i < n; ++i) {
        const glm::vec4 c = p.mvp * glm::vec4(line.points[i], 1.0f);
        s[i].in_front = c.w > 0;
        const float inv_w = s[i].in_front ? 1.0f / c.w : 0.0f;
        s[i].xy = (glm::vec2(c) * inv_w * 0.5f + 0.5f) * p.viewport;
        s[i].z = c.z * inv_w * 0.5f + 0.5f;
    }
    const float slack = 0.25f * line.tolerance;  // camera units
    const float eps = p.max_error_px;
    constexpr float kAlphaError = 1.0f / 64.0f;
    // Walks the sleeve (Zhao and Saalfeld 1997): from the anchor i, every
    // later point k narrows the interval of directions (angle), opacity
    // slopes and window-depth slopes (per pixel from the anchor) that pass
    // within the errors of it; the segment i -> j is kept while j's own lie
    // inside all three, so the points it skips are within the errors.
    for (size_t i = 0; i + 1 < n;) {
        size_t j = i + 1;
        if (s[i].in_front && s[j].in_front) {
            const glm::vec2 first = s[j].xy - s[i].xy;
            const float base = fast_atan2(first.y, first.x);
            float angle_lo = -1e30f, angle_hi = 1e30f, alpha_lo = -1e30f, alpha_hi = 1e30f, z_lo = -1e30f,
                  z_hi = 1e30f, farthest = 0;
            for (size_t k = i + 1; k < n && s[k].in_front; ++k) {
                const glm::vec2 d = s[k].xy - s[i].xy;
                const float dist = glm::length(d);
                if (dist > p.max_length_px || dist + eps < farthest) break;
                float angle = dist > 0 ? fast_atan2(d.y, d.x) - base : 0.0f;
                if (angle > 3.14159265f) angle -= 6.28318531f;
                if (angle < -3.14159265f) angle += 6.28318531f;
                const float alpha_slope = dist > 0 ? (line.opacity[k] - line.opacity[i]) / dist : 0.0f;
                const float z_slope = dist > 0 ? (s[k].z - s[i].z) / dist : 0.0f;
                // k as the end: its direction and slopes must satisfy every point skipped so far.
                if (k > i + 1 && (dist <= 0 || angle < angle_lo || angle > angle_hi || alpha_slope < alpha_lo ||
                                  alpha_slope > alpha_hi || z_slope < z_lo || z_slope > z_hi))
                    break;
                j = k;
                farthest = std::max(farthest, dist);
                // k as a skipped point: narrow the intervals.
                if (dist > eps) {
                    // asin(eps / dist) >= eps / dist, less the error of two angles (and rounding).
                    const float half = std::max(eps / dist - (2.0f * kFastAtan2Error + 1e-6f), 0.0f);
                    angle_lo = std::max(angle_lo, angle - half), angle_hi = std::min(angle_hi, angle + half);
                }
                if (dist > 0) {
                    alpha_lo = std::max(alpha_lo, alpha_slope - kAlphaError / dist);
                    alpha_hi = std::min(alpha_hi, alpha_slope + kAlphaError / dist);
                    // The window-depth error that moves the camera distance by `slack` at k.
                    const float camera = p.depth_params.y / (s[k].z * 2.0f - 1.0f + p.depth_params.x);
                    const float z_error = slack * std::fabs(p.depth_params.y) / (2.0f * camera * camera);
                    z_lo = std::max(z_lo, z_slope - z_error / dist), z_hi = std::min(z_hi, z_slope + z_error / dist);
                }
            }
        }
        out.push_back({line.points[i], line.points[j], line.opacity[i], line.opacity[j], line.strength[i],
                       line.strength[j], line.tolerance});
        i = j;
    }
}

}  // namespace kappa::render
