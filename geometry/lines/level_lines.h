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

// The same in two steps, for passes that choose their triangles: the
// per-vertex values once, then triangle by triangle.
struct LevelValues {
    std::vector<float> isophote;  // n.l (empty without isophotes)
    std::vector<float> height;    // y (empty without topo)
};
LevelValues level_values(const Mesh& mesh, const SurfaceFields& fields, const LineExtractionOptions& options);
void level_lines_of_face(const Mesh& mesh, const Face& face, const LevelValues& values,
                         const LineExtractionOptions& options, ExtractedLines& lines);

}  // namespace kappa
