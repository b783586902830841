// View-dependent line extraction on the CPU: per view, the segments of the
// line types that shaders/isolines_geom.glsl, boundary_geom.glsl and
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
#include "geometry/mesh.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace kappa {

// Hatching is a kind of stroke too (render/hatch_streamlines.h); extract_lines never makes it.
enum class LineType : int { Contour, Suggestive, Boundary, Crease, Hatching };
constexpr int kLineTypeCount = 5;
// "contours", "suggestive", "boundaries", "creases" (as in --lines), "hatching"
const char* line_type_name(LineType type);

struct LineSegment {
    glm::vec3 a, b;                 // model coordinates
    float opacity_a = 1, opacity_b = 1;    // opacity at each end (fading); 1 = full
    float strength_a = 1, strength_b = 1;  // the test value fading uses (suggestive contours: Dw kr fs^2); 1 for others
    float tolerance = 0;            // how far behind the drawn polygons the line may lie (model units):
                                    // half the longest edge of its triangle, or half its edge
};

struct LineExtractionOptions {
    bool contours = true, suggestive = true, boundaries = false, creases = true;
    bool hidden_creases = false;  // every crease, also those turned away (--hidden-lines)
    float sc_threshold = 0.05f;   // dimensionless s
    bool fade = true;
};

// A sharp edge (geometry/creases.h) with the unit normals of its two faces.
struct CreaseEdge {
    glm::vec3 a, b;
    glm::vec3 normal_a, normal_b;
};
// The sharp edges of a mesh split at its creases (SplitMesh creases and crease_faces).
std::vector<CreaseEdge> crease_edges(const Mesh& mesh, const std::vector<glm::uvec2>& creases,
                                     const std::vector<glm::uvec2>& crease_faces);

using ExtractedLines = std::array<std::vector<LineSegment>, kLineTypeCount>;

// The segments of every selected type, seen from `eye` (model coordinates).
// quantities: compute_view_quantities for the same eye; unreliable vertices
// (SurfaceFields::unreliable) draw no suggestive contours. Deterministic:
// segments come in face order (edges in input order).
ExtractedLines extract_lines(const Mesh& mesh, const SurfaceFields& fields, const ViewQuantities& quantities,
                             glm::vec3 eye, const std::vector<CreaseEdge>& creases,
                             const LineExtractionOptions& options);

// Edges used by exactly one face, as vertex pairs (a < b), sorted. With flags,
// only edges between two kFlagBoundary vertices are considered.
std::vector<glm::uvec2> boundary_edges(const Mesh& mesh, const std::vector<uint8_t>& flags);

}  // namespace kappa
