// Level lines on the CPU, as shaders/level_lines_geom.glsl: per triangle,
// where the linearly interpolated value crosses each level. Isophotes: n.l =
// (k - 1/2) / N, k = 1..N, with the fields' normal and the light in model
// coordinates; topographic lines: heights along y at first + k step.
#pragma once

#include "geometry/lines/line_extraction.h"

namespace kappa {

// Appends the selected types (options: isophotes, topo) to `lines`.
void extract_level_lines(const Mesh& mesh, const SurfaceFields& fields, const LineExtractionOptions& options,
                         ExtractedLines& lines);

}  // namespace kappa
