// Zero crossings of per-vertex fields on a triangle, shared by the line
// extractors of geometry/lines: the CPU counterpart of the shaders'
// find_crossings. A crossing on an edge is computed from the endpoint with
// the smaller vertex number, so both triangles of an edge give the same
// point bit for bit (and chain.h can join their segments).
#pragma once

#include "geometry/mesh/mesh.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>

namespace kappa::lines {

struct Crossing {
    int lo = 0, hi = 0;  // corners of the triangle
    float s = 0;         // point = mix(P[lo], P[hi], s)
};

inline Crossing edge_zero(const Face& t, int i, int j, const float f[3]) {
    Crossing c;
    c.lo = t[i] < t[j] ? i : j;
    c.hi = c.lo == i ? j : i;
    c.s = f[c.lo] / (f[c.lo] - f[c.hi]);
    return c;
}

// The two edges crossed by the zero set of f (values classified as f > 0 or
// not, so there are always 0 or 2); false when there are none.
inline bool find_crossings(const Face& t, const float f[3], Crossing& c0, Crossing& c1) {
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if ((f[i] > 0.0f) != (f[j] > 0.0f)) (n == 0 ? c0 : c1) = edge_zero(t, i, j, f), ++n;
    }
    return n == 2;
}

inline float lerp_at(const Crossing& c, const float v[3]) { return v[c.lo] + (v[c.hi] - v[c.lo]) * c.s; }
inline glm::vec3 point_at(const Crossing& c, const glm::vec3 p[3]) { return p[c.lo] + (p[c.hi] - p[c.lo]) * c.s; }

// Clips [0, 1] to where the linear function g (g0 at 0, g1 at 1) is positive.
inline bool clip_positive(float g0, float g1, glm::vec2& range) {
    if (g0 <= 0.0f && g1 <= 0.0f) return false;
    if (g0 > 0.0f && g1 > 0.0f) return true;
    const float s = g0 / (g0 - g1);
    if (g0 > 0.0f) range.y = std::min(range.y, s);
    else range.x = std::max(range.x, s);
    return range.x < range.y;
}

// Occlusion tolerance of a line across the triangle: half its longest edge.
inline float half_longest_edge(const glm::vec3 p[3]) {
    return 0.5f * std::max({glm::distance(p[0], p[1]), glm::distance(p[1], p[2]), glm::distance(p[2], p[0])});
}

}  // namespace kappa::lines
