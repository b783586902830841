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
// Threads store r without locking (a locked exchange per vertex would stall
// every read in flight): two faces met at once by two threads may both store
// theirs, and faces compared with the one overwritten. Each store is kept in
// its block's list, and a vertex whose r is no longer the one a store wrote
// becomes a candidate: every face was compared with its vertices' final r,
// or such a store exists.
//
// Limitations: which normal a vertex's r holds may depend on the threads'
// timing, so the set of candidates may differ from run to run (the creases
// found from it do not). Angles under about 0.1 degree leave no margin: then
// every vertex is a candidate.
#pragma once

#include "mesh.h"

#include <glm/vec3.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace kappa {

class CreaseCandidates {
public:
    // Faces come in `blocks` blocks, each taken in by one thread at a time.
    CreaseCandidates(size_t vertex_count, float angle_deg, size_t blocks);
    // Takes in a valid face (is_valid_face) of `block` and its face_cross (creases.h).
    void add_face(const Face& face, glm::vec3 cross, size_t block);
    // Asks for vertex v's reference to be fetched (a face's corners some faces ahead).
    void prefetch(uint32_t v) const { __builtin_prefetch(&reference_[v]); }
    // The candidates, in increasing order, once every face is in.
    std::vector<uint32_t> vertices();

private:
    uint16_t store_reference(uint32_t v, glm::vec3 direction, size_t block);

    size_t vertex_count_;
    bool everywhere_;   // no margin left: every vertex is a candidate
    float cos2_half_;  // the squared cosine of the half angle less the margin
    std::unique_ptr<std::atomic<uint16_t>[]> reference_;  // packed r, 0 while none
    std::unique_ptr<std::atomic<uint8_t>[]> candidate_;
    // Per block: (vertex << 32 | packed r) it stored. A cache line each: two threads appending to
    // neighbouring blocks' lists would otherwise pass one line to and fro at every store.
    struct alignas(64) Stores {
        std::vector<uint64_t> list;
    };
    std::vector<Stores> stored_;
};

}  // namespace kappa
