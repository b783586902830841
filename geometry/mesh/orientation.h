// Meshes whose faces are all wound the wrong way (normals pointing inside)
// draw badly: the visible side counts as back-facing, so suggestive contours
// (drawn where n.v > 0) vanish and shading darkens. Drawing turns them the
// right way round; `kappa curvature` keeps the input's orientation, whose
// normals its signs are relative to (conventions.md).
//
// Inside out: the signed volume enclosed by the faces, relative to the
// vertices' centroid, is negative and at least half the unsigned sum of the
// same tetrahedra. That holds for closed meshes with inward normals and for
// nearly closed ones (scans with holes); open sheets, whose signed volume
// has no meaning, mostly have both signs and are left alone.
#pragma once

#include "mesh.h"
#include "vertex_faces.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace kappa {

// Six times the signed and the unsigned volumes of the tetrahedra (vertex
// centroid, face), summed over the faces in parallel (block sums joined in
// order: the same whatever the thread count). face_survey.h sums them in its
// pass over the faces.
struct EnclosedVolumes {
    double signed_sum = 0, unsigned_sum = 0;
};
EnclosedVolumes enclosed_volumes(const Mesh& mesh);
glm::dvec3 vertex_centroid(const Mesh& mesh);
// One face's term: six times the signed volume of (centroid, face); 0 for a
// face with a missing corner or a volume that is not finite.
inline double tetrahedron_volume6(const Mesh& mesh, const Face& f, glm::dvec3 centroid) {
    const size_t n = mesh.positions.size();
    if (f[0] >= n || f[1] >= n || f[2] >= n) return 0;
    const glm::dvec3 a = glm::dvec3(mesh.positions[f[0]]) - centroid, b = glm::dvec3(mesh.positions[f[1]]) - centroid,
                     c = glm::dvec3(mesh.positions[f[2]]) - centroid;
    const double v = glm::dot(a, glm::cross(b, c));
    return std::isfinite(v) ? v : 0.0;
}

bool is_inside_out(const EnclosedVolumes& volumes);
bool is_inside_out(const Mesh& mesh);
// The reverse test: normals clearly pointing outside (signed volume
// positive and at least half the unsigned sum).
bool is_outside_out(const EnclosedVolumes& volumes);
bool is_outside_out(const Mesh& mesh);
// Reverses every face's winding (normals turn round). With vf (the mesh's
// vertex-face rows), they are made the turned mesh's, as build_vertex_faces
// would build them.
void flip_faces(Mesh& mesh, VertexFaces* vf = nullptr);

}  // namespace kappa
