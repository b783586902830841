// Chains line segments into polylines: segments that share an end point
// (bit-identical positions, as extract_lines produces across triangles) are
// joined into one path; a point shared by one segment or by more than two
// ends a path. Closed loops come back closed (first point == last point).
#pragma once

#include "geometry/lines/line_extraction.h"

#include <vector>

namespace kappa {

struct Polyline {
    std::vector<glm::vec3> points;
    std::vector<float> opacity;   // per point (LineSegment opacities)
    std::vector<float> strength;  // per point (LineSegment strengths)
    float tolerance = 0;          // the largest of its segments' (line_extraction.h)
    bool closed() const { return points.size() > 2 && points.front() == points.back(); }
};

// Deterministic: the result depends only on the order of `segments`.
std::vector<Polyline> chain_segments(const std::vector<LineSegment>& segments);

}  // namespace kappa
