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

namespace kappa {

bool is_inside_out(const Mesh& mesh);
// The reverse test: normals clearly pointing outside (signed volume
// positive and at least half the unsigned sum).
bool is_outside_out(const Mesh& mesh);
// Reverses every face's winding (normals turn round).
void flip_faces(Mesh& mesh);

}  // namespace kappa
