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
// One face's term: six times the signed volume of (centroid, face),
// (p0 - centroid) . ((p1 - p0) x (p2 - p0)), the cross product in float as a
// face's normal is (face_cross, creases.h), the rest in double; 0 for a face
// with a missing corner or a volume that is not finite. The pass over the
// faces (face_survey.h) takes the same term with the dot product in float
// too, from the cross product it also packs for the crease candidates.
inline double tetrahedron_volume6(glm::vec3 corner0, glm::vec3 cross, glm::dvec3 centroid) {
    const double v = glm::dot(glm::dvec3(corner0) - centroid, glm::dvec3(cross));
    return std::isfinite(v) ? v : 0.0;
}
inline double tetrahedron_volume6(const Mesh& mesh, const Face& f, glm::dvec3 centroid) {
    const size_t n = mesh.positions.size();
    if (f[0] >= n || f[1] >= n || f[2] >= n) return 0;
    const glm::vec3 p0 = mesh.positions[f[0]];
    return tetrahedron_volume6(p0, glm::cross(mesh.positions[f[1]] - p0, mesh.positions[f[2]] - p0), centroid);
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
