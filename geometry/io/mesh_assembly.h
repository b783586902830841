// Shared last steps of every reader: polygons and triangle strips into
// triangles, vertex-index checks, and the final sanity checks of a mesh.
#pragma once

#include "geometry/mesh/mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace kappa::io {

inline bool valid_index(int64_t index, size_t vertex_count) {
    return index >= 0 && uint64_t(index) < vertex_count;
}

// Throws "NAME: WHAT NUMBER refers to vertex INDEX but the file has N vertices".
[[noreturn]] void fail_bad_index(const std::string& name, const char* what, uint64_t number, int64_t index,
                                 size_t vertex_count);

// Checks every index of a polygon, then appends its fan triangulation
// (v0, v[i], v[i+1]); polygons with fewer than 3 corners add nothing.
void add_polygon(const std::string& name, const char* what, uint64_t number, const int64_t* indices,
                 size_t count, size_t vertex_count, std::vector<Face>& faces);

// Appends the triangles of a strip list: -1 (or, for unsigned index types,
// the all-ones value given as restart) starts a new strip; triangle k of a
// strip is (s[k], s[k+1], s[k+2]) with the first two swapped for odd k, so all
// triangles keep the strip's orientation; triangles that repeat an index
// (used to stitch strips together) are dropped.
void add_triangle_strips(const std::string& name, uint64_t number, const int64_t* indices, size_t count,
                         int64_t restart, size_t vertex_count, std::vector<Face>& faces);

// Final checks of a loaded mesh: at least one vertex, finite coordinates.
// Throws MeshLoadError naming the first bad vertex.
void check_loaded_mesh(const std::string& name, const Mesh& mesh);

}  // namespace kappa::io
