// View-independent curvature lines on the CPU, the tests of
// shaders/lines/curvature_lines_geom.glsl, per triangle with no unreliable vertex:
//   parabolic:  K = k1 k2 = 0
//   mean-zero:  H = (k1 + k2) / 2 = 0
//   ridges and valleys (as rtsc; Ohtake et al. 2004): where the derivative e
//     of the larger-magnitude principal curvature kmax along its own
//     direction crosses zero at a maximum of |kmax| (e falls along the
//     direction where kmax > 0: a ridge; rises where kmax < 0: a valley),
//     kept where |kmax| > rv_threshold / fs, faded towards it. The direction
//     has no sign: the triangle's directions (and e, odd in them) are turned
//     to agree with its first vertex's.
#pragma once

#include "geometry/lines/line_extraction.h"

namespace kappa {

// Appends the selected types (options: parabolic, mean_zero, ridges,
// valleys) to `lines`.
void extract_curvature_lines(const Mesh& mesh, const SurfaceFields& fields, const LineExtractionOptions& options,
                             ExtractedLines& lines);
// The same for one triangle (for passes that choose their triangles).
void curvature_lines_of_face(const Mesh& mesh, const Face& face, const SurfaceFields& fields,
                             const LineExtractionOptions& options, ExtractedLines& lines);

}  // namespace kappa
