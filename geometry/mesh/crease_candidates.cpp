#include "crease_candidates.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

// r packed in 16 bits: three signed 5-bit components, round(15 n / max |n_k|), under a set bit 15 (0 is
// "none yet"). Any direction serves as r, so the rounding (under 3 degrees) costs only a little of the
// half angle's slack, and the references take 2 bytes a vertex.
uint16_t CreaseCandidates::pack_reference(glm::vec3 n) {
    const float scale = 15.0f / std::max(std::fabs(n.x), std::max(std::fabs(n.y), std::fabs(n.z)));
    uint32_t packed = 1u << 15;
    for (int k = 0; k < 3; ++k) {
        const float x = n[k] * scale;
        packed |= (uint32_t(int(x + (x >= 0 ? 0.5f : -0.5f))) & 31u) << (5 * k);  // rounded
    }
    return uint16_t(packed);
}

CreaseCandidates::CreaseCandidates(size_t vertex_count, float angle_deg)
    : vertex_count_(vertex_count), reference_(new std::atomic<uint16_t>[vertex_count]()) {
    // edge_bends.cpp calls a pair a crease when the float dot product of its unit normals (face_normal:
    // the cross product over its float length) is under cos_limit, rounded to float. Cross products within
    // h of r are within 2h of each other; the unit normals' directions differ from theirs by a few float
    // roundings (under 1e-6 radians) and their float dot product from the cosine of their angle by a few
    // more: 2h = acos(cos_limit + 4e-6) keeps every such pair at cos_limit or above.
    const float cos_limit = std::cos(angle_deg * float(M_PI) / 180.0f);
    const double c = double(cos_limit) + 4e-6;
    everywhere_ = !(angle_deg > 0) || !(c < 1.0);
    const double half = everywhere_ ? 0.0 : 0.5 * std::acos(std::max(c, -1.0));
    // add_face's test runs in float on the cross product and r: its roundings (a few float epsilons of
    // |c|^2 |r|^2, under 1e-6 of the squared cosine) are covered by 1e-5 more.
    cos2_half_ = float(std::cos(half) * std::cos(half) + 1e-5);
    everywhere_ = everywhere_ || !(cos2_half_ < 1.0f);
}

std::vector<uint32_t> CreaseCandidates::vertices() {
    std::vector<uint32_t> out;
    for (size_t v = 0; v < vertex_count_; ++v)
        if (everywhere_ || reference_[v].load(std::memory_order_relaxed) == kCandidate) out.push_back(uint32_t(v));
    return out;
}

}  // namespace kappa
