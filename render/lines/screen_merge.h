// Fewer, longer segments for the same drawing. On a fine mesh a line is cut
// into one segment per triangle, often shorter than a pixel, and each is
// drawn as a quad reaching a line width and a pixel beyond its ends: most
// of the fragments a software rasteriser shades are those overlapping caps.
// A chained polyline (geometry/lines/chain.h) is walked from its first point
// and each segment is extended over the following points for as long as
// every point it skips stays within `max_error_px` of it on screen, its
// opacity within 1/64 of the linear one, and its camera distance (as
// lines_frag.glsl interpolates window depth) within a quarter of the
// occlusion tolerance. Points behind the eye are never skipped. (The
// directions' sleeve is kept a little narrower than the exact one: each
// point's half-width is eps / distance, below asin(eps / distance), less
// twice fast_atan2's error.)
#pragma once

#include "geometry/lines/chain.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <vector>

namespace kappa::render {

struct ScreenMergeParams {
    glm::mat4 mvp{1.0f};
    glm::vec2 viewport{1, 1};  // pixels
    glm::vec2 depth_params{0, 1};  // (P[2][2], P[3][2]): window depth -> camera distance, as lines_frag.glsl
    float max_error_px = 0.2f;
    float max_length_px = 48.0f;  // longer segments gain nothing and interpolate depth over more
};

// atan2(y, x) within kFastAtan2Error radians (a polynomial after reduction to
// the first octant): the sleeve runs it at every point of every line, where
// the library's atan2f took a tenth of the CPU line pass.
constexpr float kFastAtan2Error = 2e-5f;
float fast_atan2(float y, float x);

// Appends the merged segments of `line` (points in model coordinates, the
// polyline's tolerance on every segment) to `out`.
void merge_on_screen(const Polyline& line, const ScreenMergeParams& params, std::vector<LineSegment>& out);

}  // namespace kappa::render
