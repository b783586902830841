// OFF reading (Geomview's Object File Format): the keyword [ST][C][N][n]OFF,
// '#' comments, counts "NV NF [NE]", one vertex per line (extra per-vertex
// values such as normals, colours or texture coordinates are ignored), then
// faces "N i0 ... iN-1 [colour]" as polygons, fan-triangulated.
#pragma once

#include "geometry/mesh/mesh.h"
#include "io_errors.h"

#include <cstddef>
#include <string>

namespace kappa {

// Reads an OFF file from memory; `name` prefixes error messages. Throws
// MeshLoadError.
Mesh read_off(const char* data, size_t size, const std::string& name);

namespace io {
// True if the data starts (after blank lines and comments) with an OFF keyword.
bool looks_like_off(const char* data, size_t size);
}  // namespace io

}  // namespace kappa
