// Software prefetching for the passes that gather through an index array.
//
// On a real mesh a vertex's faces, and a face's vertices, lie far apart in
// memory (bunny-1M, two steps of Loop subdivision: a vertex's faces span
// 600,000 face indices at the median), so those gathers wait on a cache miss
// for nearly every element: most of the curvature passes' time. The index
// arrays themselves are read in order, so an address a few dozen entries
// ahead is known early enough to ask for it. Prefetches change no result.
#pragma once

#include "mesh.h"
#include "vertex_faces.h"

#include <cstdint>

namespace kappa {

// Per-face data of the corner kAhead entries after entry k of vf.corners.
template <typename T>
inline void prefetch_face_ahead(const VertexFaces& vf, uint32_t k, const T* per_face) {
    constexpr uint32_t kAhead = 24;  // about four vertices
    if (k + kAhead < vf.corners.size()) __builtin_prefetch(per_face + vf.corners[k + kAhead] / 3);
}

// Per-vertex data of the corners of face i + kAhead, for each array given.
template <typename... T>
inline void prefetch_corners_ahead(const Mesh& mesh, size_t i, const T*... per_vertex) {
    constexpr size_t kAhead = 8;
    if (i + kAhead >= mesh.faces.size()) return;
    const Face& f = mesh.faces[i + kAhead];
    for (int j = 0; j < 3; ++j) (__builtin_prefetch(per_vertex + f[j]), ...);
}

}  // namespace kappa
