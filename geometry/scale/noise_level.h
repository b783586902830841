// Noise level of a mesh: the standard deviation of the vertices' random
// displacement off a smooth surface, in model units and relative to the
// median edge length. Used to choose smoothing widths (auto_smoothing.h).
//
// Method (a local regression noise estimate, cf. Hastie, Tibshirani &
// Friedman, "The Elements of Statistical Learning", sec. 3.2: residual
// variance RSS / (n - p); and the per-vertex polynomial height fits of
// Cazals & Pouget 2005, "Estimating differential quantities using
// polynomial fitting of osculating jets"): for a sample of vertices, take
// the vertex's 2-ring (n points, the vertex included), express it in the
// vertex's normal frame (x, y tangent, z along the normal) and fit a full
// cubic height function z = poly3(x, y) (p = 10 coefficients) by least
// squares. Where the surface is smooth the cubic absorbs it up to 4th-order
// terms, so the residual is the noise: s_i^2 = RSS_i / (n_i - p) is an
// unbiased estimate of sigma^2 for noise along the normal. Per vertex,
// s_i^2 / sigma^2 ~ chi2(k) / k with k = n_i - p; the estimate is the median
// over vertices of s_i^2 / m(k), m(k) = (1 - 2 / (9k))^3 the median of
// chi2(k) / k (Wilson & Hilferty 1931), so edges, corners and outliers of
// a minority of vertices do not move it.
//
// Vertices with fewer than p + 4 points in their 2-ring or an ill-posed fit
// (points not spread in the tangent plane) are skipped. At most about 16384
// vertices are used, every ceil(V / 16384)-th in input order: bunny-1M takes
// about 40 ms on 2 threads. The result does not depend on the thread count.
//
// Measured accuracy (tests/test_geometry_noise_level.cpp): clean spheres,
// tori and ellipsoids give relative <= 0.0012; normal noise of eta = 0.005
// to 0.1 median edge lengths is recovered within 3%; it is biased low at
// larger eta, where the vertex normals that give the frames are noisy too
// (0.91 to 1.01 times eta at 0.2, 0.82 to 0.91 at 0.5).
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace kappa {

struct NoiseLevel {
    float sigma = 0;        // noise standard deviation along the normal, model units
    float median_edge = 0;  // median length of the sampled vertices' edges (each edge at most twice)
    float relative = 0;     // sigma / median_edge (0 when median_edge is 0)
    size_t samples = 0;     // vertices whose fit contributed
};

// `vf` from build_vertex_faces(mesh); `normals` unit vertex normals (any
// orientation; zero vectors mark vertices to skip), one per vertex.
NoiseLevel estimate_noise_level(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& normals);

// Its median_edge alone (no fits).
float sampled_median_edge(const Mesh& mesh, const VertexFaces& vf);

}  // namespace kappa
