// Level lines on the CPU, as shaders/lines/level_lines_geom.glsl: per triangle,
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
// The same in steps, for a caller that runs several per-vertex passes over
// one range of vertices while it is in cache: arrays of the right size
// (empty where off), then the values of the vertices [begin, end).
void begin_level_values(size_t vertex_count, const LineExtractionOptions& options, LevelValues& out);
void level_values(const Mesh& mesh, const SurfaceFields& fields, const LineExtractionOptions& options, size_t begin,
                  size_t end, LevelValues& out);
void level_lines_of_face(const Mesh& mesh, const Face& face, const LevelValues& values,
                         const LineExtractionOptions& options, ExtractedLines& lines);

}  // namespace kappa
