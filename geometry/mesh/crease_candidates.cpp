#include "crease_candidates.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

// r packed in 16 bits: three signed 5-bit components, round(15 n / max |n_k|), under a set bit 15 (0 is
// "none yet"). Any direction serves as r, so the rounding (under 3 degrees) costs only a little of the
// half angle's slack; the references take 2 bytes a vertex, and each packed value's unit vector comes
// from one small table (unit_references).
uint16_t pack(glm::vec3 n) {
    const float scale = 15.0f / std::max(std::fabs(n.x), std::max(std::fabs(n.y), std::fabs(n.z)));
    uint32_t packed = 1u << 15;
    for (int k = 0; k < 3; ++k) {
        const float x = n[k] * scale;
        packed |= (uint32_t(int(x + (x >= 0 ? 0.5f : -0.5f))) & 31u) << (5 * k);  // rounded
    }
    return uint16_t(packed);
}

float component(uint32_t packed, int k) { return float(int32_t(packed << (27 - 5 * k)) >> 27); }  // sign-extended

// Every packed r as a unit vector (32768 of them, 384 KiB: they stay in the cache), so that a corner's
// test is one dot product of unit vectors.
const std::vector<glm::vec3>& unit_references() {
    static const std::vector<glm::vec3> table = [] {
        std::vector<glm::vec3> t(1u << 15);
        for (uint32_t p = 0; p < t.size(); ++p) {
            const glm::vec3 r(component(p, 0), component(p, 1), component(p, 2));
            const float length = glm::length(r);
            t[p] = length > 0 ? r / length : glm::vec3(0.0f);  // 0: never packed (one component is +-15)
        }
        return t;
    }();
    return table;
}

}  // namespace

CreaseCandidates::CreaseCandidates(size_t vertex_count, float angle_deg, size_t blocks)
    : vertex_count_(vertex_count), reference_(new std::atomic<uint16_t>[vertex_count]()),
      candidate_(new std::atomic<uint8_t>[vertex_count]()), stored_(blocks) {
    // edge_bends.cpp calls a pair a crease when the float dot product of its unit normals (face_normal:
    // the cross product over its float length) is under cos_limit, rounded to float. Cross products within
    // h of r are within 2h of each other; the unit normals' directions differ from theirs by a few float
    // roundings (under 1e-6 radians) and their float dot product from the cosine of their angle by a few
    // more: 2h = acos(cos_limit + 4e-6) keeps every such pair at cos_limit or above.
    const float cos_limit = std::cos(angle_deg * float(M_PI) / 180.0f);
    const double c = double(cos_limit) + 4e-6;
    everywhere_ = !(angle_deg > 0) || !(c < 1.0);
    const double half = everywhere_ ? 0.0 : 0.5 * std::acos(std::max(c, -1.0));
    // The test below runs in float on unit vectors (each within a few 1e-7 of unit length): its roundings
    // (a few 1e-7 of the products) are covered by 1e-5 more.
    cos2_half_ = float(std::cos(half) * std::cos(half) + 1e-5);
    everywhere_ = everywhere_ || !(cos2_half_ < 1.0f);
}

void CreaseCandidates::add_face(const Face& face, glm::vec3 cross, size_t block) {
    if (everywhere_) return;
    // As face_normal: no normal where the float length is 0 or not finite (edge_bends.cpp gives such a
    // face no angle): its corners are candidates, for the exact pass to see.
    const float length2 = glm::dot(cross, cross);
    const bool degenerate = !(length2 > 0 && std::isfinite(length2));
    const glm::vec3 normal = degenerate ? glm::vec3(0.0f) : cross / std::sqrt(length2);
    const std::vector<glm::vec3>& unit = unit_references();
    for (int k = 0; k < 3; ++k) {
        const uint32_t v = face[k];
        if (degenerate) {
            candidate_[v].store(1, std::memory_order_relaxed);
            continue;
        }
        uint16_t packed = reference_[v].load(std::memory_order_relaxed);
        if (packed == 0) packed = store_reference(v, cross, block);  // the first face here
        // The angle between the face's normal and r is at most the half angle: cos^2 >= cos^2(half), cos > 0.
        const float d = glm::dot(normal, unit[packed & 0x7fffu]);
        if (!(d > 0 && d * d >= cos2_half_)) candidate_[v].store(1, std::memory_order_relaxed);
    }
}

uint16_t CreaseCandidates::store_reference(uint32_t v, glm::vec3 direction, size_t block) {
    const uint16_t packed = pack(direction);
    reference_[v].store(packed, std::memory_order_relaxed);
    std::vector<uint64_t>& stores = stored_[block].list;
    if (stores.capacity() == 0) stores.reserve(32768);  // about the vertices a block meets first
    stores.push_back(uint64_t(v) << 32 | packed);
    return packed;
}

std::vector<uint32_t> CreaseCandidates::vertices() {
    for (const Stores& stores : stored_)
        for (const uint64_t s : stores.list)
            if (reference_[s >> 32].load(std::memory_order_relaxed) != uint16_t(s))  // overwritten
                candidate_[s >> 32].store(1, std::memory_order_relaxed);
    std::vector<uint32_t> out;
    for (size_t v = 0; v < vertex_count_; ++v)
        if (everywhere_ || candidate_[v].load(std::memory_order_relaxed)) out.push_back(uint32_t(v));
    return out;
}

}  // namespace kappa
