// Everything kappa estimates per vertex, following Rusinkiewicz 2004:
// normal, principal curvatures and directions, and the derivative of
// curvature C in the principal frame (conventions.md: a=C111, b=C112,
// c=C122, d=C222). All arrays have one entry per input vertex.
#pragma once

#include "curvature/estimator.h"
#include "scale/noise_level.h"
#include "geometry/curvature/vertex_flags.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace kappa {

// How compute_surface_fields estimates: the estimator, and Gaussian
// smoothing widths (sigma) in model units; 0 disables a stage.
struct SmoothingOptions {
    float normals = 0;       // smooth normals before curvature is estimated
    float curvature = 0;     // smooth the curvature tensor
    float dcurv = 0;         // smooth the derivative-of-curvature tensor
    bool automatic = false;  // choose the widths left at 0 from the mesh's noise level
    Estimator estimator = Estimator::rusinkiewicz;  // geometry/curvature/estimator.h
};

struct SurfaceFields {
    std::vector<glm::vec3> normals;      // unit, outward
    std::vector<float> point_areas;      // mixed Voronoi area (Meyer et al. 2002)
    std::vector<float> k1, k2;           // principal curvatures, k1 >= k2
    std::vector<glm::vec3> d1, d2;       // unit principal directions, d1 x d2 = n
    std::vector<glm::vec4> dcurv;        // (a, b, c, d) in the (d1, d2) frame
    std::vector<uint8_t> flags;          // VertexFlag bits
    SmoothingOptions smoothing;          // the widths actually used (automatic: as requested)
    NoiseLevel noise;                    // the estimate behind automatic widths (zero otherwise)

    size_t size() const { return normals.size(); }
    // Whether curvature and C are there (compute_surface_normals leaves them out).
    bool has_curvature() const { return k1.size() == normals.size(); }
    // Whether vertex v's estimate is flagged unreliable; false without flags.
    bool unreliable(size_t v) const { return v < flags.size() && (flags[v] & kFlagUnreliable); }
};

// |C|, the norm of the derivative tensor C = (a, b, c, d) in any orthonormal
// frame: |C|^2 = a^2 + 3b^2 + 3c^2 + d^2 (conventions.md). For glm::vec4
// (float) or glm::dvec4 (double).
template <typename Vec4>
auto dcurv_norm(const Vec4& C) {
    return std::sqrt(C.x * C.x + 3 * C.y * C.y + 3 * C.z * C.z + C.w * C.w);
}

}  // namespace kappa
