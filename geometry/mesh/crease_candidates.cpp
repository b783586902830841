#include "crease_candidates.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

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
    // A face packed as r is within kPackAngleDeg of r: within the half angle when the test above passes
    // every angle up to kPackAngleDeg (cos2_half_ includes the margin; 1e-5 more covers the test's roundings).
    const double pack_cos = std::cos(kPackAngleDeg * M_PI / 180.0);
    same_pack_passes_ = !everywhere_ && double(cos2_half_) + 1e-5 <= pack_cos * pack_cos;
}

std::vector<uint32_t> CreaseCandidates::vertices() {
    std::vector<uint32_t> out;
    for (size_t v = 0; v < vertex_count_; ++v)
        if (everywhere_ || reference_[v].load(std::memory_order_relaxed) == kCandidate) out.push_back(uint32_t(v));
    return out;
}

}  // namespace kappa
