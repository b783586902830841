// Wavefront OBJ reading through tinyobjloader: positions and faces only.
#pragma once

#include "geometry/mesh/mesh.h"
#include "io_errors.h"

#include <cstddef>
#include <string>

namespace kappa {

// Reads an OBJ file from memory. Every `v` line becomes one vertex, in file
// order (curvature is reported per input vertex); faces use the position
// index of each corner (relative indices resolved) and polygons are
// fan-triangulated; a vertex index out of range (including one beyond 32
// bits) is an error that quotes it as written. Texture coordinates, normals,
// materials, lines and points are ignored. `name` prefixes error messages. Throws MeshLoadError.
Mesh read_obj(const char* data, size_t size, const std::string& name);

}  // namespace kappa
