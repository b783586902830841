// View-dependent line extraction on the CPU: per view, the segments of the
// line types that shaders/lines/isolines_geom.glsl, boundary_geom.glsl and
// crease_geom.glsl draw on the GPU, with the same tests, so vector output
// (strokes) and raster output show the same lines. No OpenGL.
//
//   contours:    zeros of n.v (contour normals), per triangle (DeCarlo et al. 2003)
//   suggestive:  zeros of kr where Dw kr * fs^2 > s and n.v > 0, each segment
//                clipped where a test fails inside it (as rtsc); with fading,
//                strength rises from 0 at s to 1 at s + max(s, 0.05)
//   boundaries:  edges used by one face
//   creases:     sharp edges turned towards the viewer; a sharp edge between a
//                front- and a back-facing face is also occluding contour
//
// A zero crossing on an edge is computed from the endpoint with the smaller
// vertex number, so the two triangles sharing the edge produce the same point
// bit for bit, and segments can be chained by their end points (chain.h).
// Hidden parts are not removed here: that needs the depth of the rendered
// surface (render/stroke_visibility.h).
#pragma once

#include "geometry/lines/view_quantities.h"
#include "geometry/mesh/mesh.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace kappa {

// The --lines types drawn as strokes, by their --lines names. Hatching is a
// kind of stroke too (render/hatching/hatch_streamlines.h); extract_lines never makes it.
enum class LineType : int {
    Contour, Suggestive, Boundary, Crease,
    SuggestiveHighlight, Dwkr,                   // view-dependent, here
    Ridge, Valley, Parabolic, MeanZero,          // view-independent (curvature_lines.h)
    Isophote, Topo,                              // level lines (level_lines.h)
    ApparentRidge, PrincipalHighlight,           // view-dependent (view_ridges.h)
    Hatching
};
constexpr int kLineTypeCount = 15;
// "contours", "suggestive", "boundaries", "creases", "suggestive-highlights", "dwkr", "ridges",
// "valleys", "parabolic", "mean-zero", "isophotes", "topo", "apparent-ridges",
// "principal-highlights" (as in --lines), "hatching"
const char* line_type_name(LineType type);
// Zero sets of view-dependent fields (contours, suggestive contours and
// highlights, Dw kr lines): with --detail they may lie the detail scale
// behind the drawn polygons, so their occlusion tolerance grows with it.
inline bool is_view_isoline(LineType t) {
    return t == LineType::Contour || t == LineType::Suggestive || t == LineType::SuggestiveHighlight ||
           t == LineType::Dwkr;
}

struct LineSegment {
    glm::vec3 a, b;                 // model coordinates
    float opacity_a = 1, opacity_b = 1;    // opacity at each end (fading); 1 = full
    float strength_a = 1, strength_b = 1;  // the test value fading uses (suggestive contours: Dw kr fs^2); 1 for others
    float tolerance = 0;            // how far behind the drawn polygons the line may lie (model units):
                                    // half the longest edge of its triangle, or half its edge
};

// Levels first + k step, k = 0 .. count - 1 (level lines: isophotes, topographic lines).
struct LevelSet {
    float first = 0, step = 1;
    int count = 0;
};
// Isophotes at n.l = (k - 1/2) / N, k = 1..N (shading's light, --isophotes N).
LevelSet isophote_level_set(int count);
// Topographic lines: N heights evenly across a bounding sphere's extent along
// y (centre y, radius), the first and last half a step inside (--topo N).
LevelSet topo_level_set(float center_y, float radius, int count);

struct LineExtractionOptions {
    bool contours = true, suggestive = true, boundaries = false, creases = true;
    bool suggestive_highlights = false, dwkr = false;
    bool ridges = false, valleys = false, parabolic = false, mean_zero = false;
    bool isophotes = false, topo = false;
    bool apparent_ridges = false, principal_highlights = false;
    float ar_threshold = 1.0f;    // dimensionless: apparent ridges where sqrt(q1) fs > it
    float ph_threshold = 0.2f;    // dimensionless: principal highlights where (kmax^2 - kmin^2) n.v fs^2 > it
    bool hidden_creases = false;  // every crease, also those turned away (--hidden-lines)
    // As rtsc's back-face culling: no line but contours on a triangle turned
    // away from the eye at all three corners (faces_eye; the renderer's
    // default, off with --hidden-lines).
    bool cull_back_faces = false;
    float sc_threshold = 0.05f;   // dimensionless s: suggestive contours (Dw kr fs^2 > s) and dwkr (= s)
    float sh_threshold = 0.1f;    // dimensionless: suggestive highlights where -Dw kr fs^2 > it
    float rv_threshold = 1.5f;    // dimensionless: ridges and valleys where |kmax| > it / fs
    float feature_size = 1;       // fs
    bool fade = true;             // suggestive contours and highlights, ridges and valleys
    // Level lines: isophotes of n.l for the light direction (model coordinates,
    // unit) and topographic lines of the height y, at these levels.
    glm::vec3 light{0, 0, 1};
    LevelSet isophote_levels = isophote_level_set(4);
    LevelSet topo_levels{0, 1, 12};
};

// A sharp edge (geometry/mesh/creases.h) with the unit normals of its two faces.
struct CreaseEdge {
    glm::vec3 a, b;
    glm::vec3 normal_a, normal_b;
};
// The sharp edges of a mesh split at its creases (SplitMesh creases and crease_faces).
std::vector<CreaseEdge> crease_edges(const Mesh& mesh, const std::vector<glm::uvec2>& creases,
                                     const std::vector<glm::uvec2>& crease_faces);

using ExtractedLines = std::array<std::vector<LineSegment>, kLineTypeCount>;

// Whether triangle t is turned towards `eye` at one corner or more: n.(eye - p) > 0
// with the fields' normals (the test of LineExtractionOptions::cull_back_faces).
bool faces_eye(const Mesh& mesh, const SurfaceFields& fields, const Face& t, glm::vec3 eye);

// The segments of every selected type, seen from `eye` (model coordinates).
// quantities: compute_view_quantities for the same eye; unreliable vertices
// (SurfaceFields::unreliable) draw no suggestive contours. Deterministic:
// segments come in face order (edges in input order).
ExtractedLines extract_lines(const Mesh& mesh, const SurfaceFields& fields, const ViewQuantities& quantities,
                             glm::vec3 eye, const std::vector<CreaseEdge>& creases,
                             const LineExtractionOptions& options);

// The view-dependent lines of one triangle (contours, suggestive contours,
// suggestive highlights, Dw kr lines; no crease edges), for passes that
// choose their own triangles (render/cpu_isolines.h).
void extract_view_lines_of_face(const Mesh& mesh, const Face& face, const SurfaceFields& fields,
                                const ViewQuantities& quantities, const LineExtractionOptions& options,
                                ExtractedLines& lines);

// The segments of sharp edges seen from `eye`: with o.creases those turned towards it (every one with
// o.hidden_creases), with o.contours those between a face turned towards it and one turned away, as
// contours (as shaders/lines/crease_geom.glsl). Appended to `lines`.
void append_crease_segments(const std::vector<CreaseEdge>& creases, glm::vec3 eye, const LineExtractionOptions& options,
                            ExtractedLines& lines);

// Edges used by exactly one face, as vertex pairs (a < b), sorted. With flags,
// only edges between two kFlagBoundary vertices are considered.
std::vector<glm::uvec2> boundary_edges(const Mesh& mesh, const std::vector<uint8_t>& flags);
// The segments of those edges (tolerance: half the edge), appended to `out`.
void append_boundary_segments(const Mesh& mesh, const std::vector<glm::uvec2>& edges, std::vector<LineSegment>& out);

}  // namespace kappa
