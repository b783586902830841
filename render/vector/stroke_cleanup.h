// Optional clean-up of visible strokes (render/vector/strokes.h) before they are
// written, all lengths in image pixels (RenderSettings: --min-stroke,
// --simplify, --taper, --width-by-strength; README "Vector output").
#pragma once

#include "render/vector/strokes.h"

#include <vector>

namespace kappa::render {

// Removes strokes whose length is under min_length (0: none).
void drop_short_strokes(std::vector<Stroke>& strokes, float min_length);

// Douglas-Peucker simplification (Douglas and Peucker 1973): every removed
// point lies within `tolerance` of the simplified path. Opacity is kept at
// the remaining points. 0: unchanged.
void simplify_strokes(std::vector<Stroke>& strokes, float tolerance);

// Length of a stroke's path.
float stroke_length(const Stroke& stroke);

}  // namespace kappa::render
