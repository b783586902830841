// Merging chained segments on screen (render/lines/screen_merge.h): fewer
// segments, every dropped point within the errors of the segment that
// replaces it, and nothing merged across a point behind the eye.
#include <catch2/catch.hpp>

#include "render/lines/screen_merge.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace kappa;

namespace {

glm::vec2 to_window(const render::ScreenMergeParams& p, glm::vec3 x) {
    const glm::vec4 c = p.mvp * glm::vec4(x, 1.0f);
    return (glm::vec2(c) / c.w * 0.5f + 0.5f) * p.viewport;
}

float distance_to_segment(glm::vec2 q, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float t = glm::clamp(glm::dot(q - a, ab) / glm::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
    return glm::distance(q, a + t * ab);
}

render::ScreenMergeParams camera_at_z(float distance) {
    render::ScreenMergeParams p;
    const glm::mat4 projection = glm::perspective(glm::radians(30.0f), 4.0f / 3.0f, 0.1f, 100.0f);
    p.mvp = projection * glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -distance));
    p.viewport = {800, 600};
    p.depth_params = {projection[2][2], projection[3][2]};
    return p;
}

// A circle of radius r in the z = 0 plane, n segments, opacity `opacity(angle)`.
template <typename Opacity>
Polyline circle(float r, int n, Opacity opacity) {
    Polyline line;
    for (int i = 0; i <= n; ++i) {
        const float a = 6.2831853f * float(i) / float(n);
        line.points.push_back({r * std::cos(a), r * std::sin(a), 0.0f});
        line.opacity.push_back(opacity(a));
        line.strength.push_back(1.0f);
    }
    line.tolerance = 0.01f;
    return line;
}

}  // namespace

TEST_CASE("merging on screen keeps every point within 0.2 px of its segment and drops most of them",
          "[render][screen-merge]") {
    const render::ScreenMergeParams p = camera_at_z(3.0f);
    // About 300 px across in 4000 steps: segments of a quarter of a pixel.
    const Polyline line = circle(1.0f, 4000, [](float) { return 1.0f; });
    std::vector<LineSegment> merged;
    render::merge_on_screen(line, p, merged);
    INFO(merged.size() << " segments for " << line.points.size() - 1);
    CHECK(merged.size() < (line.points.size() - 1) / 8);
    // Consecutive, from the first point to the last.
    REQUIRE(!merged.empty());
    CHECK(merged.front().a == line.points.front());
    CHECK(merged.back().b == line.points.back());
    for (size_t i = 1; i < merged.size(); ++i) CHECK(merged[i].a == merged[i - 1].b);
    // Each input point lies within the error of the merged segment spanning it.
    size_t s = 0;
    float worst = 0;
    for (const glm::vec3& x : line.points) {
        while (s + 1 < merged.size() && x == merged[s].b) ++s;
        worst = std::max(worst, distance_to_segment(to_window(p, x), to_window(p, merged[s].a), to_window(p, merged[s].b)));
    }
    CHECK(worst <= p.max_error_px * 1.01f);
}

TEST_CASE("merging on screen follows opacity and stops at points behind the eye", "[render][screen-merge]") {
    const render::ScreenMergeParams p = camera_at_z(3.0f);
    // Opacity fading around the circle: a coarser merge where opacity is flat.
    const Polyline fading = circle(1.0f, 4000, [](float a) { return a < 3.14159f ? 1.0f : 0.5f + 0.5f * std::sin(8 * a); });
    std::vector<LineSegment> merged;
    render::merge_on_screen(fading, p, merged);
    size_t i = 0;
    float worst = 0;
    for (const LineSegment& seg : merged) {
        while (fading.points[i] != seg.a) ++i;
        const size_t first = i;
        while (fading.points[i] != seg.b) ++i;
        for (size_t k = first; k <= i; ++k) {
            const float t = float(k - first) / float(std::max<size_t>(1, i - first));
            worst = std::max(worst, std::fabs(seg.opacity_a + (seg.opacity_b - seg.opacity_a) * t - fading.opacity[k]));
        }
    }
    CHECK(worst < 2.0f / 64.0f);  // 1/64 along the screen, measured here by point count

    // A line through the eye plane: the points behind it are kept as they are.
    Polyline through;
    for (int k = 0; k <= 100; ++k) {
        through.points.push_back({0.5f, 0.0f, -1.0f + 0.06f * float(k)});  // z from -1 to 5; the eye is at z = 3
        through.opacity.push_back(1), through.strength.push_back(1);
    }
    through.tolerance = 0.01f;
    merged.clear();
    render::merge_on_screen(through, p, merged);
    size_t behind = 0;
    for (const glm::vec3& x : through.points) behind += x.z >= 3.0f;
    CHECK(merged.size() >= behind);
}

TEST_CASE("fast_atan2 is within its stated error of atan2 in every direction", "[render][screen-merge]") {
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
        const double a = 6.283185307179586 * i / 200000.0 - 3.141592653589793;
        for (const double r : {1e-3, 1.0, 700.0}) {
            const float x = float(r * std::cos(a)), y = float(r * std::sin(a));
            worst = std::max(worst, std::fabs(double(render::fast_atan2(y, x)) - std::atan2(double(y), double(x))));
        }
    }
    INFO("largest error " << worst << " rad");
    CHECK(worst <= double(render::kFastAtan2Error));
    CHECK(render::fast_atan2(0.0f, 0.0f) == 0.0f);
}
