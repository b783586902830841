// Analytic test shapes as triangle meshes, counter-clockwise from outside.
// Used by tests, benchmarks and the built-in default model.
#pragma once

#include "mesh.h"

#include <cstdint>

namespace kappa {

// Icosahedron subdivided `levels` times, vertices on the sphere of radius r.
Mesh make_icosphere(float radius, int levels);

// Latitude/longitude sphere: `rings` bands from pole to pole, `segments`
// around. Has skinny triangles near the poles.
Mesh make_uv_sphere(float radius, int rings, int segments);

// Torus around the z axis: major radius R, minor radius r, `nu` segments
// around the big circle, `nv` around the tube. Vertex (i, j) sits at
// u = 2 pi i / nu, v = 2 pi j / nv with v = 0 on the outer equator.
Mesh make_torus(float major_radius, float minor_radius, int nu, int nv);

// Axis-aligned ellipsoid with semi-axes (a, b, c), as a deformed icosphere.
Mesh make_ellipsoid(float a, float b, float c, int levels);

// Flat square grid in the z = 0 plane, [-size/2, size/2]^2, n x n quads.
Mesh make_grid(float size, int n);

// Randomly jittered sphere: an icosphere whose vertices are moved randomly
// along the surface by up to `jitter` (0..1) times half the shortest edge,
// giving irregular and skinny triangles that never fold. Deterministic for a
// given seed.
Mesh make_jittered_sphere(float radius, int levels, float jitter, uint32_t seed);

// Moves every vertex along its unit normal (the area-weighted mean of its
// faces' normals, computed before any vertex moves) by an independent
// Gaussian of standard deviation `sigma` (model units): the "normal noise"
// of scans. Deterministic for a given seed on every platform (mt19937 and
// Box-Muller, no std::normal_distribution). Vertices without a face stay.
void add_normal_noise(Mesh& mesh, float sigma, uint32_t seed);

}  // namespace kappa
