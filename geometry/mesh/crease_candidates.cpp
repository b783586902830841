#include "crease_candidates.h"

#include <algorithm>
#include <cmath>

namespace kappa {

CreaseCandidateTest::CreaseCandidateTest(float angle_deg) {
    // edge_bends.cpp calls a pair a crease when the float dot product of its unit normals (face_normal:
    // the cross product over its float length) is under cos_limit, rounded to float. Normals within h of
    // a direction are within 2h of each other; the unit normals' directions differ from their cross
    // products' by a few float roundings (under 1e-6 radians) and their float dot product from the cosine
    // of their angle by a few more: 2h = acos(cos_limit + 4e-6) keeps every such pair at cos_limit or above.
    const float cos_limit = std::cos(angle_deg * float(M_PI) / 180.0f);
    const double c = double(cos_limit) + 4e-6;
    // A face's normal lies within kPackAngleDeg of its pack: packs within h - kPackAngleDeg of r leave the
    // normals within h of r.
    const double room = angle_deg > 0 && c < 1.0 ? 0.5 * std::acos(std::max(c, -1.0)) - kPackAngleDeg * M_PI / 180.0
                                                  : 0.0;
    // keeps()' one rounded product (a few float epsilons of the squared cosine) is covered by 1e-5 more.
    cos2_ = float(std::cos(room) * std::cos(room) + 1e-5);
    everywhere_ = !(room > 0) || !(cos2_ < 1.0f);
}

}  // namespace kappa
