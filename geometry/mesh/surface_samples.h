// Random points on a triangle mesh, uniformly distributed by area, in random
// order: every prefix of the list is itself a uniform sample of the surface.
// Hatching (render/) draws a view-dependent prefix of them as stroke seeds:
// the seed at index i is kept where the wanted number of strokes per unit of
// surface area exceeds (i + 1/2) / count * (count / area), so zooming in or
// darkening adds seeds without moving the ones already drawn.
#pragma once

#include "mesh.h"
#include "geometry/surface_fields.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace kappa {

struct SurfaceSample {
    glm::vec3 position;   // on the face
    glm::vec3 normal;     // the vertex normals interpolated, unit
    glm::vec3 direction;  // d1 interpolated, unit and tangent; zero where the vertices' d1 disagree (umbilics, noise)
    uint32_t face;
};

struct SurfaceSamples {
    std::vector<SurfaceSample> points;
    double area = 0;  // total area of the faces, which the sampling needs anyway
};

// `count` samples from a fixed pseudo-random sequence (`seed`): the same
// input gives the same samples. Faces of zero area are never chosen; a mesh
// of zero total area gives none. fields must have one entry per vertex.
SurfaceSamples sample_surface(const Mesh& mesh, const SurfaceFields& fields, size_t count, uint64_t seed = 1);

}  // namespace kappa
