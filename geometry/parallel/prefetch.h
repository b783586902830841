// Software prefetching for the passes that gather through an index array.
//
// On a real mesh a vertex's faces lie far apart in memory (bunny-1M, two
// steps of Loop subdivision: a vertex's faces span 600,000 face indices at
// the median), so the per-vertex gathers over them wait on a cache miss for
// nearly every face: most of those passes' time. The corner lists are read
// in order, so an address a few dozen entries ahead is known early enough
// to ask for it. Prefetches change no result. (The face passes' gathers of
// their three vertices gained nothing from it.)
#pragma once

#include "geometry/mesh/vertex_faces.h"

#include <cstdint>

namespace kappa {

// Per-face data of the corner kAhead entries after entry k of vf.corners.
template <typename T>
inline void prefetch_face_ahead(const VertexFaces& vf, uint32_t k, const T* per_face) {
    constexpr uint32_t kAhead = 24;  // about four vertices
    if (k + kAhead < vf.corners.size()) __builtin_prefetch(per_face + vf.corners[k + kAhead] / 3);
}

}  // namespace kappa
