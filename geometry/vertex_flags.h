// Per-vertex reliability flags. A flagged vertex still gets finite values
// (never NaN or inf); the flag says why they should not be trusted.
#pragma once

#include <cstdint>

namespace kappa {

enum VertexFlag : uint8_t {
    kFlagIsolated    = 1 << 0,  // no faces use this vertex
    kFlagDegenerate  = 1 << 1,  // every incident face has zero area
    kFlagBoundary    = 1 << 2,  // on an open boundary (one-sided neighbourhood)
    kFlagNonManifold = 1 << 3,  // on an edge shared by more than two faces
    kFlagFallback    = 1 << 4,  // the chosen estimator could not fit its full model here (a lower
                                // degree, or a zero estimate): geometry/curvature/estimate.h
};

// Bits that make a curvature estimate unreliable (everything above).
constexpr uint8_t kFlagUnreliable =
    kFlagIsolated | kFlagDegenerate | kFlagBoundary | kFlagNonManifold | kFlagFallback;

}  // namespace kappa

#include "mesh.h"
#include "vertex_faces.h"

#include <vector>

namespace kappa {

// Flags every vertex from its one-ring alone (so it is parallel and needs no
// global edge table): isolated (no face), degenerate (zero Voronoi area),
// boundary (an edge at the vertex used by one face), non-manifold (an edge
// used by three or more faces).
std::vector<uint8_t> compute_vertex_flags(const Mesh& mesh, const VertexFaces& vf,
                                          const std::vector<float>& point_areas);

}  // namespace kappa
