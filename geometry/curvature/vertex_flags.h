// Per-vertex reliability flags. A flagged vertex still gets finite values
// (never NaN or inf); the flag says why they should not be trusted. The
// first four are set by compute_vertex_basics (vertex_basics.h).
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
