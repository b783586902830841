// Pen-plotter paths (--plotter): one pen width, no line drawn twice, paths
// joined where they meet and ordered to shorten the pen's travel in the air.
//   1. Fading becomes a cut: only the parts at half ink or more are kept,
//      drawn at full ink.
//   2. Overlaps: paths are taken longest first, resampled every half pixel;
//      a sample within `radius` (1 px) of a sample of a path already kept is
//      dropped, which cuts the path there.
//   3. Paths of one line type whose ends lie within 2 radius (step 2 cuts a
//      path up to radius + half a pixel short of another) are joined.
//   4. Order: greedy nearest end (a path may be reversed), from the top-left
//      corner, line type by line type; kept only when it travels less than
//      the order it was given (so never more).
#pragma once

#include "render/vector/strokes.h"

#include <vector>

namespace kappa::render {

std::vector<Stroke> plotter_paths(std::vector<Stroke> strokes, float radius = 1.0f);

// Pen-up travel of drawing the strokes in order: from (0, 0) to the first
// point, and from each stroke's last point to the next one's first.
double pen_up_travel(const std::vector<Stroke>& strokes);

}  // namespace kappa::render
