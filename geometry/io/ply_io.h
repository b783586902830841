// PLY reading (ascii, binary little- and big-endian; any extra elements and
// properties skipped) and writing of a mesh with its per-vertex fields.
#pragma once

#include "geometry/mesh/mesh.h"
#include "../surface_fields.h"
#include "io_errors.h"

#include <cstddef>
#include <string>

namespace kappa {

// Reads a PLY file from memory. Uses the first "vertex" element (x, y, z of
// any numeric type), "face" elements (list vertex_indices or vertex_index,
// polygons fan-triangulated) and "tristrips" elements (list vertex_indices,
// -1 restarts a strip). `name` prefixes error messages. Throws MeshLoadError.
Mesh read_ply(const char* data, size_t size, const std::string& name);

// Writes the mesh and its per-vertex fields (the float properties
// x y z nx ny nz k1 k2 d1x d1y d1z d2x d2y d2z a b c d, then `uchar flags`)
// and its faces (`list uchar int vertex_indices`). Binary little-endian by
// default, ASCII on request. Throws MeshWriteError.
void write_ply(const std::string& path, const Mesh& mesh, const SurfaceFields& fields, bool binary = true);

}  // namespace kappa
