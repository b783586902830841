#include "render/vector/stroke_cleanup.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace kappa::render {

namespace {

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::distance(p, a + t * ab);
}

// Marks the points of [first, last] that the simplified path keeps.
void douglas_peucker(const std::vector<glm::vec2>& p, size_t first, size_t last, float tolerance,
                     std::vector<char>& keep) {
    // Iterative, with an explicit stack: paths can have many thousands of points.
    std::vector<std::pair<size_t, size_t>> stack{{first, last}};
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        float worst = 0;
        size_t at = a;
        for (size_t i = a + 1; i < b; ++i) {
            const float d = distance_to_segment(p[i], p[a], p[b]);
            if (d > worst) worst = d, at = i;
        }
        if (worst > tolerance) {
            keep[at] = 1;
            stack.push_back({a, at}), stack.push_back({at, b});
        }
    }
}

}  // namespace

float stroke_length(const Stroke& s) {
    float length = 0;
    for (size_t i = 0; i + 1 < s.points.size(); ++i) length += glm::distance(s.points[i], s.points[i + 1]);
    return length;
}

void drop_short_strokes(std::vector<Stroke>& strokes, float min_length) {
    if (min_length <= 0) return;
    strokes.erase(std::remove_if(strokes.begin(), strokes.end(),
                                 [&](const Stroke& s) { return stroke_length(s) < min_length; }),
                  strokes.end());
}

void simplify_strokes(std::vector<Stroke>& strokes, float tolerance) {
    if (tolerance <= 0) return;
    for (Stroke& s : strokes) {
        if (s.points.size() < 3) continue;
        std::vector<char> keep(s.points.size(), 0);
        keep.front() = keep.back() = 1;
        douglas_peucker(s.points, 0, s.points.size() - 1, tolerance, keep);
        size_t n = 0;
        for (size_t i = 0; i < s.points.size(); ++i)
            if (keep[i]) {
                s.points[n] = s.points[i], s.opacity[n] = s.opacity[i];
                if (!s.strength.empty()) s.strength[n] = s.strength[i];
                if (!s.surface.empty()) s.surface[n] = s.surface[i];
                ++n;
            }
        s.points.resize(n), s.opacity.resize(n);
        if (!s.strength.empty()) s.strength.resize(n);
        if (!s.surface.empty()) s.surface.resize(n);
    }
}

}  // namespace kappa::render
