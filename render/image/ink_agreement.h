// How much two line drawings agree, as a person comparing them would judge:
// the fraction of one drawing's ink that lies near ink of the other. Used by
// tests and benchmarks of drawing quality (ink: conventions.md, dark lines
// on white with --shading none --colormap none).
#pragma once

#include "render/image/image.h"

#include <cstddef>

namespace kappa::render {

// A pixel is ink when its darkest channel is below 128.
bool is_ink(const Rgba& c);
size_t count_ink(const Image& image);

// Fraction of a's ink pixels with an ink pixel of b within `radius` pixels
// (Euclidean distance between pixel centres). 1 when a has no ink. a and b
// must have the same size.
double ink_within(const Image& a, const Image& b, float radius);

}  // namespace kappa::render
