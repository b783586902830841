// One 64-byte record a face: everything the per-vertex passes gather from a
// face, in one cache line. They visit a vertex's faces in face order,
// scattered over memory (bunny-1M: 600,000 faces apart at the median), so
// one line a face, not one per array: those loads were most of their time.
//
// A record lives through two phases, the second written over the first in
// place (so the memory is mapped once):
//  1. geometry (face_geometry.h): the area normal, 1 / |e_j|^2, the corner
//     areas and the face's vertex indices; read by the per-vertex pass of
//     areas, normals and flags (vertex_basics.h) and by the curvature fit;
//  2. fit (curvature.h): II's harmonics and the edges in the face frame,
//     then C's harmonics (dcurvature.h), the corner areas kept as the
//     averaging weights, and each corner's frame rotation.
#pragma once

#include "geometry/mesh/mesh.h"
#include "tensor_frames.h"
#include "geometry/parallel/uninitialized_array.h"

#include <glm/vec3.hpp>
#include <cstddef>
#include <cstring>

namespace kappa {

struct alignas(64) FaceRecord {
    // Phase 1: the area normal (p1 - p0) x (p2 - p0) (0-2), then 1 / |e_j|^2
    // for the edge e_j opposite corner j (3-5).
    // Phase 2: II fitted in the face frame (t, b) (t along the edge from
    // corner 1 to corner 2, t x b the face normal; the frame itself is not
    // kept: everything later is relative to it), as its harmonics (h0, a2,
    // b2) (tensor_frames.h), then the edges in (t, b): e_0 = (x, 0), e_1 =
    // (y, z), e_2 = -e_0 - e_1. Once the face's C is fitted, C's harmonics
    // (a1, b1, a3, b3) take their place.
    float fit[6];
    // Mixed-Voronoi corner areas, the averaging weights; all 0 where the face
    // is not usable (degenerate; in phase 2 also where a fit failed), and
    // then so is everything else but the vertex indices.
    glm::vec3 weights;
    // Phase 1: the face's three vertex indices (their bits, in the first
    // three floats; every face has them). Phase 2: each corner's vertex
    // frame (tangent_frame of its normal) rotated into the face's plane
    // (sec. 3.3), as a rotation from (t, b).
    FrameRotation corners[3];

    // Phase 1 fields.
    glm::vec3 area_normal() const { return {fit[0], fit[1], fit[2]}; }
    glm::vec3 inv_edge_len2() const { return {fit[3], fit[4], fit[5]}; }
    Face face() const {
        uint32_t v[3];
        std::memcpy(v, &corners[0], sizeof v);
        return {v[0], v[1], v[2]};
    }
};
static_assert(sizeof(FaceRecord) == 64, "FaceRecord: one cache line");
static_assert(offsetof(FaceRecord, weights) == 6 * sizeof(float) &&
                  offsetof(FaceRecord, corners) == 9 * sizeof(float),
              "FaceRecord: 16 floats in order (the face passes store them as such)");

using FaceRecords = UninitializedArray<FaceRecord>;

}  // namespace kappa
