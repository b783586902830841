// The vertices where an edge may turn by more than a crease angle: the few
// around which find_creases' exact pass (edge_bends.h) must look, instead of
// every vertex of a big mesh. face_survey.cpp finds them in three passes that
// read no position twice:
//
//   1. over the faces: each face's normal direction, packed in 16 bits;
//   2. over the vertices (their rows, vertex_faces.h): each vertex's reference
//      direction r, the pack of the first face in its row;
//   3. over the faces again: a face whose pack lies more than the half angle
//      less kPackAngleDeg from the r of one of its corners makes that corner a
//      candidate (its r is replaced by a mark).
//
// A vertex that is no candidate has all its faces' normals within half the
// angle of r (each normal lies within kPackAngleDeg of its pack), so no two of
// them turn by the angle (the triangle inequality on the sphere) and none of
// its edges is a crease. The half angle is cut by a margin that covers the
// rounding of the normals and dot products edge_bends.cpp compares: the
// creases found around the candidates alone are exactly those of the whole
// pass. Degenerate faces make their corners candidates; faces with repeated or
// missing corners are no edges' faces and are left out. r depends on the rows
// alone, so the candidates are the same whatever the thread count.
//
// Limitation: angles under about 5.6 degrees (twice kPackAngleDeg and the
// margin) leave no room: then every vertex is a candidate.
#pragma once

#include "geometry/parallel/double_lanes.h"

#include <cstdint>
#include <type_traits>

namespace kappa {

class CreaseCandidateTest {
public:
    explicit CreaseCandidateTest(float angle_deg);
    // No room left under the angle: every vertex is a candidate.
    bool everywhere() const { return everywhere_; }

    // A direction packed in 16 bits: three signed 5-bit components, 15 n / max |n_k| rounded to nearest
    // (lanes::nearest), under a set bit 15. The largest component is +-15 to within float roundings and the
    // other two within 0.5 of 15 n / max |n_k|, so a direction lies within asin(0.7072 / 14.999), 2.71
    // degrees, of its packing: kPackAngleDeg rounds that up.
    static constexpr double kPackAngleDeg = 2.75;
    // Values without bit 15: a face left out (repeated or missing corners) or a vertex with no face;
    // a face without a normal (degenerate); a vertex that is a candidate.
    static constexpr uint16_t kLeftOut = 0, kNoNormal = 1, kCandidate = 2;

    // For a float or four lanes (lanes.h): the same operations lane by lane, so the same bits. Not for a
    // zero or non-finite direction (four lanes give some value there, a float is not to be asked).
    template <typename F> static auto pack_direction(F x, F y, F z) {
        using lanes::larger, lanes::magnitude;
        const F scale = 15.0f / larger(magnitude(x), larger(magnitude(y), magnitude(z)));
        auto rounded = [&](F c) { return lanes::nearest(c * scale) & 31; };  // in 5 bits
        return (1 << 15) | rounded(x) | rounded(y) << 5 | rounded(z) << 10;
    }

    // Whether a face packed as `face` keeps its corner with reference r = `reference` from being a
    // candidate: both packed directions (bit 15 set), at most the half angle less kPackAngleDeg apart.
    // For int32_t or lanes::Ints4 (lane by lane: all bits set where it does).
    template <typename I> auto keeps(I face, I reference) const {
        using F = std::conditional_t<std::is_same_v<I, int32_t>, float, lanes::Lanes>;
        auto component = [](I packed, int k) {  // sign-extended
            if constexpr (std::is_same_v<I, int32_t>) return float(int32_t(uint32_t(packed) << (27 - 5 * k)) >> 27);
            else return __builtin_convertvector((packed << (27 - 5 * k)) >> 27, lanes::Lanes);
        };
        const F fx = component(face, 0), fy = component(face, 1), fz = component(face, 2);
        const F rx = component(reference, 0), ry = component(reference, 1), rz = component(reference, 2);
        // Small integers: the dot products and squares are exact; the one product with cos2_ rounds
        // (covered by the margin in it). The angle is at most the limit: cos^2 >= cos2_ and cos > 0.
        const F d = fx * rx + fy * ry + fz * rz;
        return (face == reference) | ((d > 0.0f) & (d * d >= cos2_ * (fx * fx + fy * fy + fz * fz) *
                                                                (rx * rx + ry * ry + rz * rz)));
    }

private:
    bool everywhere_;
    float cos2_;  // the squared cosine of the half angle less the margin and kPackAngleDeg
};

}  // namespace kappa
