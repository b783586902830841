// The vertices where an edge may turn by more than a crease angle, from one
// look at each face: the few around which find_creases' exact pass
// (edge_bends.h) must look, instead of every vertex of a big mesh.
//
// Each vertex keeps a reference direction r: the normal of the first of its
// faces met. A face whose normal lies more than half the angle from the r of
// one of its corners makes that corner a candidate. A vertex that is no
// candidate has all its faces' normals within half the angle of r, so no two
// of them turn by the angle (the triangle inequality on the sphere) and none
// of its edges is a crease. The half angle is cut by a margin that covers the
// rounding of the normals and dot products edge_bends.cpp compares: the
// creases found around the candidates alone are exactly those of the whole
// pass. Degenerate faces make their corners candidates; faces with repeated
// or missing corners are no edges' faces and are left out.
//
// A vertex's r is stored once, by a compare-and-exchange from "none": of two
// threads meeting a vertex's first faces at once, one stores its r and the
// other compares with it. A candidate's r is replaced by a mark that nothing
// overwrites, so later faces around it are not compared at all.
//
// Limitations: which normal a vertex's r holds may depend on the threads'
// timing, so the set of candidates may differ from run to run (the creases
// found from it do not). Angles under about 0.1 degree leave no margin: then
// every vertex is a candidate.
#pragma once

#include "mesh.h"

#include "geometry/parallel/double_lanes.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

namespace kappa {

class CreaseCandidates {
public:
    CreaseCandidates(size_t vertex_count, float angle_deg);
    // r packed in 16 bits: three signed 5-bit components, round(15 n / max |n_k|), under a set bit 15 (0 is
    // "none yet"). Any direction serves as r, so the rounding costs only a little of the half angle's slack,
    // and the references take 2 bytes a vertex. The largest component is +-15 to within float roundings and
    // the other two within 0.5 of 15 n / max |n_k|, so a direction lies within asin(0.7072 / 14.999), 2.71
    // degrees, of its packing: kPackAngleDeg rounds that up.
    static constexpr double kPackAngleDeg = 2.75;
    // For a float or four lanes (lanes.h): the same operations lane by lane, so the same bits. Not for a
    // zero or non-finite direction.
    template <typename F> static auto pack_direction(F x, F y, F z) {
        using lanes::larger, lanes::magnitude;
        const F scale = 15.0f / larger(magnitude(x), larger(magnitude(y), magnitude(z)));
        auto rounded = [&](F c) {  // half away from zero, in 5 bits
            const F t = c * scale;
            const F away = t >= 0.0f ? t + 0.5f : t - 0.5f;
            if constexpr (std::is_same_v<F, float>) return uint32_t(int32_t(away)) & 31u;
            else return __builtin_convertvector(away, lanes::Ints4) & 31;
        };
        return (1 << 15) | rounded(x) | rounded(y) << 5 | rounded(z) << 10;
    }
    // Takes in a valid face (is_valid_face) and its face_cross (creases.h); any thread.
    void add_face(const Face& face, glm::vec3 cross) {
        if (everywhere_) return;
        const float length2 = glm::dot(cross, cross);
        const bool degenerate = !(length2 > 0 && std::isfinite(length2));
        add_face(face, cross, length2, degenerate ? kNone : uint16_t(pack_direction(cross.x, cross.y, cross.z)));
    }
    // The same with the cross product's squared length (glm::dot) and pack_direction given: a pass
    // that computes them for four faces at once (face_survey.cpp). The pack is not looked at where the
    // length is 0 or not finite.
    void add_face(const Face& face, glm::vec3 cross, float length2, uint16_t packed_cross) {
        if (everywhere_) return;
        // As face_normal: no normal where the float length is 0 or not finite (edge_bends.cpp gives such a
        // face no angle): its corners are candidates, for the exact pass to see.
        const bool degenerate = !(length2 > 0 && std::isfinite(length2));
        // The face's own packed direction: where it equals a corner's r, the face is within kPackAngleDeg of r
        // (pack_direction), and so within the half angle when same_pack_passes_: no test needed (most corners
        // of a fine mesh).
        const uint16_t mine = degenerate ? kCandidate : packed_cross;
        for (int k = 0; k < 3; ++k) {
            std::atomic<uint16_t>& reference = reference_[face[k]];
            uint16_t packed = reference.load(std::memory_order_relaxed);
            if (packed == kCandidate) continue;
            if (degenerate) {
                reference.store(kCandidate, std::memory_order_relaxed);
                continue;
            }
            if (packed == kNone) {  // the first face here: store r, or take the one another thread just stored
                if (reference.compare_exchange_strong(packed, mine, std::memory_order_relaxed)) packed = mine;
                if (packed == kCandidate) continue;
            }
            if (packed == mine && same_pack_passes_) continue;
            // The angle between the face's normal n and r is at most the half angle: cos^2 >= cos^2(half) and
            // cos > 0, with cos = c.r / (|c| |r|) for the cross product c, squared to keep off roots and
            // divisions. r's components are small integers (|r|^2 is exact); a product that underflows
            // fails the test: a candidate.
            const glm::vec3 r = unpack(packed);
            const float d = glm::dot(cross, r);
            if (!(d > 0 && d * d >= cos2_half_ * length2 * glm::dot(r, r)))
                reference.store(kCandidate, std::memory_order_relaxed);
        }
    }
    // Asks for vertex v's reference to be fetched (a face's corners some faces ahead).
    void prefetch(uint32_t v) const { __builtin_prefetch(&reference_[v]); }
    // The candidates, in increasing order, once every face is in.
    std::vector<uint32_t> vertices();

private:
    static constexpr uint16_t kNone = 0;       // no r stored yet
    static constexpr uint16_t kCandidate = 1;  // bit 15 clear: no packed r
    static float component(uint32_t packed, int k) { return float(int32_t(packed << (27 - 5 * k)) >> 27); }
    static glm::vec3 unpack(uint32_t packed) { return {component(packed, 0), component(packed, 1), component(packed, 2)}; }

    size_t vertex_count_;
    bool everywhere_;   // no margin left: every vertex is a candidate
    float cos2_half_;  // the squared cosine of the half angle less the margin
    bool same_pack_passes_;  // the half angle less the margin is at least kPackAngleDeg
    // Packed r (bit 15 set), kNone while none, kCandidate once the vertex is a candidate.
    std::unique_ptr<std::atomic<uint16_t>[]> reference_;
};

}  // namespace kappa
