// glTF 2.0 reading (.gltf: JSON with embedded or external buffers; .glb:
// the binary container) through Debian's tinygltf.
//
// Every triangle primitive (modes TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN;
// indexed or not) of the nodes of the default scene (scene 0 when none is
// named; every mesh once, untransformed, when the file has no scene) is
// read, with the node transforms applied (matrix, or translation, rotation
// and scale; parents first). Triangles of a node whose global transform has
// a negative determinant (a mirror, e.g. scale [-1, 1, 1]) are reversed, as
// the spec's winding rule asks, so that faces stay counter-clockwise seen
// from outside. NORMAL attributes are not read: kappa's normals come from
// the transformed faces, so they are what the inverse transpose of the
// transform would give, under any scale. Points and lines are skipped; morph
// targets, skins and materials are ignored. Corners are welded like STL's
// (vertex_weld.h): exactly equal positions become one vertex, in order of
// first occurrence. Sparse or non-float positions, indices out of range,
// accessors outside their buffers and a scene with no triangle are errors,
// "NAME: problem" in one line (MeshLoadError).
#pragma once

#include "geometry/mesh/mesh.h"
#include "io_errors.h"

#include <cstddef>
#include <string>

namespace kappa {

// `name` is the file's path: external buffers are read relative to its folder.
Mesh read_gltf(const char* data, size_t size, const std::string& name);

namespace io {
// The binary container's magic "glTF".
bool looks_like_glb(const char* data, size_t size);
// JSON whose top level has an "asset" member, as every glTF 2.0 file does.
bool looks_like_gltf_json(const char* data, size_t size);
}  // namespace io

}  // namespace kappa
