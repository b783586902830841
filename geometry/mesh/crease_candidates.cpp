#include "crease_candidates.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

// r packed as three signed 8-bit components, round(127 n / max |n_k|), under a set bit 24 (0 is "none
// yet"). Any direction serves as r, so the rounding costs nothing, and unpacking it takes no table.
uint32_t pack(glm::vec3 n) {
    const float scale = 127.0f / std::max(std::fabs(n.x), std::max(std::fabs(n.y), std::fabs(n.z)));
    uint32_t packed = 1u << 24;
    for (int k = 0; k < 3; ++k) {
        const float x = n[k] * scale;
        packed |= uint32_t(uint8_t(int8_t(int(x + (x >= 0 ? 0.5f : -0.5f))))) << (8 * k);  // rounded
    }
    return packed;
}

glm::vec3 unpack(uint32_t packed) {
    return {float(int8_t(packed & 255)), float(int8_t(packed >> 8 & 255)), float(int8_t(packed >> 16 & 255))};
}

}  // namespace

CreaseCandidates::CreaseCandidates(size_t vertex_count, float angle_deg, size_t blocks)
    : vertex_count_(vertex_count), reference_(new std::atomic<uint32_t>[vertex_count]()),
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
    // The test below runs in float: its roundings (a few 1e-7 of the products) are covered by 1e-5 more.
    cos2_half_ = float(std::cos(half) * std::cos(half) + 1e-5);
    everywhere_ = everywhere_ || !(cos2_half_ < 1.0f);
}

void CreaseCandidates::add_face(const Face& face, glm::vec3 cross, size_t block) {
    if (everywhere_) return;
    // As face_normal: no normal where the float length is 0 or not finite (edge_bends.cpp gives such a
    // face no angle): its corners are candidates, for the exact pass to see.
    const float length2 = glm::dot(cross, cross);
    const bool degenerate = !(length2 > 0 && std::isfinite(length2));
    for (int k = 0; k < 3; ++k) {
        const uint32_t v = face[k];
        if (degenerate) {
            candidate_[v].store(1, std::memory_order_relaxed);
            continue;
        }
        uint32_t packed = reference_[v].load(std::memory_order_relaxed);
        if (packed == 0) packed = store_reference(v, cross, block);  // the first face here
        // The angle between the face's normal and r is at most the half angle: cos^2 >= cos^2(half), cos > 0.
        const glm::vec3 r = unpack(packed);
        const float d = glm::dot(cross, r);
        if (!(d > 0 && d * d >= cos2_half_ * length2 * glm::dot(r, r)))
            candidate_[v].store(1, std::memory_order_relaxed);
    }
}

uint32_t CreaseCandidates::store_reference(uint32_t v, glm::vec3 direction, size_t block) {
    const uint32_t packed = pack(direction);
    reference_[v].store(packed, std::memory_order_relaxed);
    std::vector<uint64_t>& stores = stored_[block].list;
    if (stores.capacity() == 0) stores.reserve(32768);  // about the vertices a block meets first
    stores.push_back(uint64_t(v) << 32 | packed);
    return packed;
}

std::vector<uint32_t> CreaseCandidates::vertices() {
    for (const Stores& stores : stored_)
        for (const uint64_t s : stores.list)
            if (reference_[s >> 32].load(std::memory_order_relaxed) != uint32_t(s))  // overwritten
                candidate_[s >> 32].store(1, std::memory_order_relaxed);
    std::vector<uint32_t> out;
    for (size_t v = 0; v < vertex_count_; ++v)
        if (everywhere_ || candidate_[v].load(std::memory_order_relaxed)) out.push_back(uint32_t(v));
    return out;
}

}  // namespace kappa
