// STL reading, ASCII and binary. Binary files are recognised by their size
// (84 + 50 * triangle count), not by the "solid" prefix, which many binary
// exporters also write into their 80-byte header.
#pragma once

#include "geometry/mesh/mesh.h"
#include "io_errors.h"

#include <cstddef>
#include <string>

namespace kappa {

// Reads an STL file from memory and welds exactly equal corner positions
// into shared vertices (first-occurrence order). `name` prefixes error
// messages. Throws MeshLoadError.
Mesh read_stl(const char* data, size_t size, const std::string& name);

namespace io {
// True if the size matches a binary STL with the triangle count it declares.
bool looks_like_binary_stl(const char* data, size_t size);
// True if the data starts (after blanks) with "solid".
bool looks_like_ascii_stl(const char* data, size_t size);
}  // namespace io

}  // namespace kappa
