#include "face_survey.h"

#include "crease_candidates.h"
#include "creases.h"
#include "edge_table.h"

#include "geometry/io/prefault.h"
#include "geometry/parallel/double_lanes.h"
#include "geometry/parallel/parallel.h"
#include "geometry/parallel/uninitialized_array.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <numeric>

namespace kappa {

namespace {

using Test = CreaseCandidateTest;
constexpr size_t kBlock = 65536;  // faces; block sums joined in order: independent of the thread count
constexpr size_t kAhead = 64;     // faces (or vertices) whose data is fetched early: it lies all over memory

// A block's volume sums: four faces at a time in double lanes (each face's term in float), the faces
// of a block's end one at a time. Joined in a fixed order: the same bits whatever the thread count.
struct FaceSums {
    lanes::Doubles4 signed4{}, unsigned4{};
    double signed_rest = 0, unsigned_rest = 0;
    void add(float v) { if (std::isfinite(v)) signed_rest += v, unsigned_rest += std::fabs(v); }
    void add(lanes::Lanes v) {
        v = (v - v == 0.0f) ? v : 0.0f;  // not finite: 0
        signed4 += __builtin_convertvector(v, lanes::Doubles4);
        unsigned4 += __builtin_convertvector(lanes::magnitude(v), lanes::Doubles4);
    }
    EnclosedVolumes total() const {
        return {((signed4[0] + signed4[1]) + (signed4[2] + signed4[3])) + signed_rest,
                ((unsigned4[0] + unsigned4[1]) + (unsigned4[2] + unsigned4[3])) + unsigned_rest};
    }
};

// Pass 1 (crease_candidates.h): each face's volume term (tetrahedron_volume6's, in float) and, where
// `packs` is given, its packed direction, from one cross product (face_cross).
uint16_t pack_of(const Face& face, glm::vec3 cross, size_t nv) {
    if (!is_valid_face(face, nv)) return Test::kLeftOut;
    // As face_normal: no normal where the float length is 0 or not finite (edge_bends.cpp gives such a
    // face no angle).
    const float length2 = glm::dot(cross, cross);
    if (!(length2 > 0 && std::isfinite(length2))) return Test::kNoNormal;
    return uint16_t(Test::pack_direction(cross.x, cross.y, cross.z));
}

void survey_one(const Mesh& mesh, size_t f, glm::vec3 apex, uint16_t* packs, FaceSums& sums) {
    const size_t nv = mesh.vertex_count();
    const Face& face = mesh.faces[f];
    if (face[0] >= nv || face[1] >= nv || face[2] >= nv) {  // no volume, no edges
        if (packs) packs[f] = Test::kLeftOut;
        return;
    }
    const glm::vec3 cross = face_cross(mesh, face);
    sums.add(glm::dot(mesh.positions[face[0]] - apex, cross));
    if (packs) packs[f] = pack_of(face, cross, nv);
}

// Four faces at once (lanes.h): the same operations as one face's, so the same bits.
void survey_four(const Mesh& mesh, size_t f, glm::vec3 apex, uint16_t* packs, FaceSums& sums) {
    using lanes::Lanes;
    const Face* faces = &mesh.faces[f];
    const size_t nv = mesh.vertex_count();
    for (int j = 0; j < 4; ++j)
        if (faces[j][0] >= nv || faces[j][1] >= nv || faces[j][2] >= nv) {
            for (int i = 0; i < 4; ++i) survey_one(mesh, f + i, apex, packs, sums);
            return;
        }
    auto corner = [&](int k, int axis) {
        const glm::vec3* p = mesh.positions.data();
        return Lanes{p[faces[0][k]][axis], p[faces[1][k]][axis], p[faces[2][k]][axis], p[faces[3][k]][axis]};
    };
    const lanes::Vec3<Lanes> p0{corner(0, 0), corner(0, 1), corner(0, 2)};
    const lanes::Vec3<Lanes> c = lanes::cross(lanes::Vec3<Lanes>{corner(1, 0), corner(1, 1), corner(1, 2)} - p0,
                                              lanes::Vec3<Lanes>{corner(2, 0), corner(2, 1), corner(2, 2)} - p0);
    const lanes::Vec3<Lanes> from{Lanes{} + apex.x, Lanes{} + apex.y, Lanes{} + apex.z};
    sums.add(lanes::dot(p0 - from, c));
    if (!packs) return;
    const Lanes length2 = lanes::dot(c, c);
    const lanes::Ints4 normal = (length2 > 0.0f) & (length2 <= std::numeric_limits<float>::max());
    lanes::Ints4 out = Test::pack_direction(c.x, c.y, c.z);
    // A face with a repeated corner has a zero cross product: where every face has a normal, none is left out.
    if (__builtin_expect(!lanes::all(normal), 0)) {
        auto index = [&](int k) {
            return lanes::Ints4{int32_t(faces[0][k]), int32_t(faces[1][k]), int32_t(faces[2][k]), int32_t(faces[3][k])};
        };
        const lanes::Ints4 i0 = index(0), i1 = index(1), i2 = index(2);
        const lanes::Ints4 valid = (i0 != i1) & (i1 != i2) & (i0 != i2);  // is_valid_face (every corner is a vertex)
        out = valid ? (normal ? out : Test::kNoNormal) : Test::kLeftOut;
    }
    using Shorts8 = uint16_t __attribute__((vector_size(16)));
    using Shorts4 = uint16_t __attribute__((vector_size(8)));
    const Shorts8 halves = Shorts8(out);  // the low half of each lane (little-endian)
    const Shorts4 narrow = __builtin_shufflevector(halves, halves, 0, 2, 4, 6);
    std::memcpy(&packs[f], &narrow, sizeof narrow);
}

// Pass 2: each vertex's r, the pack of the first face in its row that is not left out (kLeftOut where
// none is); a face without a normal there makes the vertex a candidate at once.
UninitializedArray<uint16_t> references(const VertexFaces& vf, const uint16_t* packs, size_t nv,
                                        std::vector<uint32_t>& candidates) {
    UninitializedArray<uint16_t> out(nv);
    std::mutex joining;
    io::prefault(out.data(), nv * sizeof(uint16_t));
    const uint32_t* offsets = vf.offsets.data();
    const uint32_t* corners = vf.corners.data();
    parallel_for_chunks(nv, [&](size_t first, size_t last) {
        std::vector<uint32_t> found;
        for (size_t v = first; v < last; ++v) {
            if (v + kAhead < nv && offsets[v + kAhead] < offsets[v + kAhead + 1])
                __builtin_prefetch(&packs[corners[offsets[v + kAhead]] / 3]);
            uint16_t r = Test::kLeftOut;
            for (uint32_t i = offsets[v]; i < offsets[v + 1]; ++i)
                if (const uint16_t p = packs[corners[i] / 3]; p != Test::kLeftOut) {
                    r = p == Test::kNoNormal ? Test::kCandidate : p;
                    break;
                }
            out[v] = r;
            if (r == Test::kCandidate) found.push_back(uint32_t(v));
        }
        if (found.empty()) return;
        const std::lock_guard<std::mutex> lock(joining);
        candidates.insert(candidates.end(), found.begin(), found.end());
    });
    return out;
}

// Pass 3: each face against its corners' r. Only kCandidate is ever stored, so the outcome does not
// depend on the order in which threads meet the faces. The vertices a block marks are also noted in
// `marks` (some twice, where two threads mark one at once).
class FaceTest {
public:
    FaceTest(const Mesh& mesh, const uint16_t* packs, uint16_t* references, const Test& test)
        : mesh_(mesh), packs_(packs), references_(references), test_(test) {}

    void one(size_t f, std::vector<uint32_t>& marks) const {
        const uint16_t pack = packs_[f];
        if (pack == Test::kLeftOut) return;
        const Face& face = mesh_.faces[f];
        for (int k = 0; k < 3; ++k) {
            const uint16_t r = load(face[k]);
            if (r == Test::kCandidate) continue;
            if (pack == Test::kNoNormal || !test_.keeps(int32_t(pack), int32_t(r))) mark(face[k], marks);
        }
    }

    void four(size_t f, std::vector<uint32_t>& marks) const {
        const uint16_t* p = &packs_[f];
        if (!(p[0] & p[1] & p[2] & p[3] & 0x8000)) {  // some face left out or without a normal
            for (int j = 0; j < 4; ++j) one(f + j, marks);
            return;
        }
        const Face* faces = &mesh_.faces[f];
        const lanes::Ints4 pack{p[0], p[1], p[2], p[3]};
        lanes::Ints4 r[3];
        for (int k = 0; k < 3; ++k) r[k] = lanes::Ints4{load(faces[0][k]), load(faces[1][k]), load(faces[2][k]),
                                                       load(faces[3][k])};
        // Mostly (on fine meshes) every corner's r is the face's own pack: nothing to test.
        if (lanes::all((r[0] == pack) & (r[1] == pack) & (r[2] == pack))) return;
        lanes::Ints4 moved{};  // bit k: corner k becomes a candidate
        for (int k = 0; k < 3; ++k) moved |= (r[k] != Test::kCandidate) & ~test_.keeps(pack, r[k]) & (1 << k);
        if (__builtin_expect(moved[0] | moved[1] | moved[2] | moved[3], 0))
            for (int j = 0; j < 4; ++j)
                for (int k = 0; k < 3; ++k)
                    if (moved[j] & (1 << k)) mark(faces[j][k], marks);
    }

    void prefetch(size_t f) const {
        for (int k = 0; k < 3; ++k)
            if (const uint32_t v = mesh_.faces[f][k]; v < mesh_.vertex_count()) __builtin_prefetch(&references_[v]);
    }

private:
    // Relaxed atomic loads and stores (the references are written by other threads meanwhile).
    uint16_t load(uint32_t v) const { return __atomic_load_n(&references_[v], __ATOMIC_RELAXED); }
    void mark(uint32_t v, std::vector<uint32_t>& marks) const {
        __atomic_store_n(&references_[v], Test::kCandidate, __ATOMIC_RELAXED);
        marks.push_back(v);
    }

    const Mesh& mesh_;
    const uint16_t* packs_;
    uint16_t* references_;
    const Test& test_;
};

// The vertices marked kCandidate, in increasing order: from the passes' notes where they are few, else
// from a pass over the references.
std::vector<uint32_t> marked(const UninitializedArray<uint16_t>& references, std::vector<uint32_t> noted) {
    if (noted.size() <= references.size() / 64) {
        std::sort(noted.begin(), noted.end());
        noted.erase(std::unique(noted.begin(), noted.end()), noted.end());
        return noted;
    }
    const size_t nv = references.size(), blocks = (nv + kBlock - 1) / kBlock;
    std::vector<std::vector<uint32_t>> found(blocks);
    parallel_for_chunked(blocks, [&](size_t b) {
        for (size_t v = b * kBlock; v < std::min(nv, (b + 1) * kBlock); ++v)
            if (references[v] == Test::kCandidate) found[b].push_back(uint32_t(v));
    }, 1);
    std::vector<uint32_t> out;
    for (const std::vector<uint32_t>& b : found) out.insert(out.end(), b.begin(), b.end());
    return out;
}

// Calls body(block, first face, end) for each block of faces, in parallel.
template <typename Body> void for_face_blocks(size_t nf, Body&& body) {
    const size_t blocks = (nf + kBlock - 1) / kBlock;
    parallel_for_chunked(blocks, [&](size_t b) { body(b, b * kBlock, std::min(nf, (b + 1) * kBlock)); }, 1);
}

}  // namespace

FaceSurvey survey_faces(const Mesh& mesh, const VertexFaces& vf, float crease_angle_deg) {
    return survey_faces(mesh, vf, crease_angle_deg, glm::vec3(vertex_centroid(mesh)));
}

FaceSurvey survey_faces(const Mesh& mesh, const VertexFaces& vf, float crease_angle_deg, glm::vec3 apex) {
    FaceSurvey out;
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    if (nv == 0 || nf == 0) return out;
    const Test test(crease_angle_deg);
    const bool candidates = crease_angle_deg > 0;
    const bool packing = candidates && !test.everywhere();
    // Fresh memory: its pages mapped in one call on every thread cost about half what first touches do.
    UninitializedArray<uint16_t> packs(packing ? nf : 0);
    io::prefault(packs.data(), packs.size() * sizeof(uint16_t));
    uint16_t* const pack_out = packing ? packs.data() : nullptr;

    std::vector<EnclosedVolumes> partial((nf + kBlock - 1) / kBlock);
    for_face_blocks(nf, [&](size_t b, size_t begin, size_t end) {
        FaceSums sums;
        size_t f = begin;
        for (; f + 4 <= end; f += 4) {
            // The corners of faces some way ahead, fetched early.
            for (size_t g = f + kAhead; g < std::min(end, f + kAhead + 4); ++g)
                for (int k = 0; k < 3; ++k)
                    if (const uint32_t v = mesh.faces[g][k]; v < nv) __builtin_prefetch(&mesh.positions[v]);
            survey_four(mesh, f, apex, pack_out, sums);
        }
        for (; f < end; ++f) survey_one(mesh, f, apex, pack_out, sums);
        partial[b] = sums.total();
    });
    for (const EnclosedVolumes& p : partial)
        out.volumes.signed_sum += p.signed_sum, out.volumes.unsigned_sum += p.unsigned_sum;
    if (!candidates) return out;
    if (!packing) {
        out.crease_candidates.resize(nv);
        std::iota(out.crease_candidates.begin(), out.crease_candidates.end(), 0u);
        return out;
    }

    std::vector<uint32_t> noted;
    UninitializedArray<uint16_t> refs = references(vf, packs.data(), nv, noted);
    const FaceTest faces(mesh, packs.data(), refs.data(), test);
    std::vector<std::vector<uint32_t>> marks((nf + kBlock - 1) / kBlock);
    for_face_blocks(nf, [&](size_t b, size_t begin, size_t end) {
        size_t f = begin;
        for (; f + 4 <= end; f += 4) {
            for (size_t g = f + kAhead; g < std::min(end, f + kAhead + 4); ++g) faces.prefetch(g);
            faces.four(f, marks[b]);
        }
        for (; f < end; ++f) faces.one(f, marks[b]);
    });
    for (const std::vector<uint32_t>& m : marks) noted.insert(noted.end(), m.begin(), m.end());
    out.crease_candidates = marked(refs, std::move(noted));
    return out;
}

std::vector<uint32_t> crease_candidates(const Mesh& mesh, const VertexFaces& vf, float angle_deg) {
    return survey_faces(mesh, vf, angle_deg).crease_candidates;
}

}  // namespace kappa
