// Which line families can cross a triangle, from one word per vertex, so
// the CPU line pass (render/lines/cpu_lines.h) runs the exact per-triangle tests
// of geometry/lines only where a line may be. Conservative: a family is
// skipped only when its exact test must fail, because
//   - a zero set (n.v, kr, Dw kr - s, K, H) crosses a triangle only where its
//     vertex values change sign;
//   - a clipped line (suggestive contours and highlights, ridges and
//     valleys, apparent ridges, principal highlights) is kept only where a
//     linearly interpolated strength exceeds its threshold, which needs one
//     vertex above it (and n.v > 0 at one vertex, for the suggestive kinds);
//   - principal highlights need kmax of one sign and unreliable vertices
//     draw none of the curvature-based kinds;
//   - an apparent ridge crosses an edge only where the vectors tm = D_t1 q1 t1
//     at its ends have dot <= 0, and a principal highlight only where v.dmax
//     changes sign with the triangle's dmax turned to agree: neither can
//     happen when the three vectors (dmax turned so that its largest
//     component is positive) have the same signs, component by component, none
//     near zero, and (highlights) v.dmax so turned has one strict sign;
//   - a level line crosses only where the vertices lie in different bands
//     between consecutive levels;
//   - with options.cull_back_faces, only contours are drawn on a triangle
//     turned away from the eye at all three corners (faces_eye).
#pragma once

#include "geometry/lines/level_lines.h"
#include "geometry/lines/line_extraction.h"
#include "geometry/lines/view_quantities.h"
#include "geometry/lines/view_ridges.h"

#include <cstdint>
#include <vector>

namespace kappa::render {

// The families of line types of the CPU line pass, each with its own choice of clusters.
enum LineFamily : uint8_t { kViewLines = 1, kCurvatureLines = 2, kViewRidges = 4, kIsophotes = 8, kTopo = 16 };

struct LinePrefilter {
    std::vector<uint64_t> bits;  // per vertex
    LineExtractionOptions options;  // types on, thresholds
    ViewRidgeOptions ridge_options;
    glm::vec3 eye{0};  // model coordinates
    // The families of `wanted` that may have a line on triangle t.
    uint8_t families_on(const Face& t, uint8_t wanted) const;
};

// options: as for the per-triangle tests, with isophote and topo levels and
// cull_back_faces; eye: where the view is from (model coordinates)
// (isophote_levels, topo_levels); the other inputs may
// be empty where their families are off; only: empty, or one flag per vertex,
// non-zero at the vertices of the triangles that will be asked about (the
// others get no bits). Parallel over vertices.
LinePrefilter make_line_prefilter(const Mesh& mesh, const SurfaceFields& fields, const ViewQuantities& view,
                                  const std::vector<ViewRidgeVertex>& ridges, const ViewRidgeOptions& ridge_options,
                                  const LevelValues& levels, const LineExtractionOptions& options, glm::vec3 eye,
                                  const std::vector<uint8_t>& only = {});
// The same into `out`, kept by a caller that makes one every frame: its bits
// are resized, not cleared, so where `only` is zero they keep what they held.
void make_line_prefilter(const Mesh& mesh, const SurfaceFields& fields, const ViewQuantities& view,
                         const std::vector<ViewRidgeVertex>& ridges, const ViewRidgeOptions& ridge_options,
                         const LevelValues& levels, const LineExtractionOptions& options, glm::vec3 eye,
                         const std::vector<uint8_t>& only, LinePrefilter& out);
// The same in steps, for a caller that runs several per-vertex passes over
// one range of vertices while it is in cache: the options and the size,
// then the bits of the vertices [begin, end) (any thread, disjoint ranges).
void begin_line_prefilter(size_t vertex_count, const ViewRidgeOptions& ridge_options,
                          const LineExtractionOptions& options, glm::vec3 eye, LinePrefilter& out);
void line_prefilter_bits(const Mesh& mesh, const SurfaceFields& fields, const ViewQuantities& view,
                         const std::vector<ViewRidgeVertex>& ridges, const LevelValues& levels,
                         const std::vector<uint8_t>& only, size_t begin, size_t end, LinePrefilter& out);

}  // namespace kappa::render
