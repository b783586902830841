#include "subdivide.h"

#include <algorithm>
#include <unordered_map>

namespace kappa {

Mesh subdivide_at_midpoints(const Mesh& in) {
    Mesh out;
    out.positions = in.positions;
    out.faces.reserve(in.faces.size() * 4);
    std::unordered_map<uint64_t, uint32_t> midpoint;  // edge (smaller << 32 | larger) -> its midpoint
    midpoint.reserve(in.faces.size() * 2);
    auto mid = [&](uint32_t a, uint32_t b) {
        const uint64_t key = uint64_t(std::min(a, b)) << 32 | std::max(a, b);
        const auto [it, fresh] = midpoint.emplace(key, uint32_t(out.positions.size()));
        if (fresh) out.positions.push_back(0.5f * (in.positions[a] + in.positions[b]));
        return it->second;
    };
    for (const Face& f : in.faces) {
        const uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
        out.faces.push_back({f[0], ab, ca});
        out.faces.push_back({ab, f[1], bc});
        out.faces.push_back({ca, bc, f[2]});
        out.faces.push_back({ab, bc, ca});
    }
    return out;
}

}  // namespace kappa
