#include "position_bounds.h"

#include "geometry/parallel/parallel.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

PositionBounds position_bounds(const std::vector<glm::vec3>& positions) {
    constexpr size_t kBlock = 65536;
    const size_t n = positions.size();
    std::vector<PositionBounds> blocks((n + kBlock - 1) / kBlock);
    parallel_for_chunked(
        blocks.size(),
        [&](size_t b) {
            PositionBounds out;  // in registers: stored through a reference, every step waited on the last
            for (size_t v = b * kBlock; v < std::min(n, (b + 1) * kBlock); ++v) {
                const glm::vec3 p = positions[v];
                if (std::isfinite(p.x + p.y + p.z)) out.lo = glm::min(out.lo, p), out.hi = glm::max(out.hi, p);
            }
            blocks[b] = out;
        },
        1);
    PositionBounds all;
    for (const PositionBounds& b : blocks) all.lo = glm::min(all.lo, b.lo), all.hi = glm::max(all.hi, b.hi);
    return all;
}

}  // namespace kappa
