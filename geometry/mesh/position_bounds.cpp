#include "position_bounds.h"

#include "geometry/parallel/lanes.h"
#include "geometry/parallel/parallel.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace kappa {

namespace {

using lanes::Lanes;

// Bounds of points [first, last) one at a time, leaving out those with a non-finite coordinate.
void add_points(PositionBounds& out, const glm::vec3* p, size_t first, size_t last) {
    for (size_t v = first; v < last; ++v)
        if (std::isfinite(p[v].x) && std::isfinite(p[v].y) && std::isfinite(p[v].z))
            out.lo = glm::min(out.lo, p[v]), out.hi = glm::max(out.hi, p[v]);
}

// The same for [first, first + 4 * groups), four points (twelve floats, three lanes) at a time: lane j of
// the k-th lanes holds coordinate (4 k + j) % 3. False, with `out` unchanged, where some coordinate is not
// finite (x - x is then NaN, and NaN stays in a sum).
bool add_groups(PositionBounds& out, const glm::vec3* p, size_t first, size_t groups) {
    const char* bytes = reinterpret_cast<const char*>(p + first);
    Lanes lo[3], hi[3], nonfinite{};
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 4; ++j) lo[k][j] = out.lo[(4 * k + j) % 3], hi[k][j] = out.hi[(4 * k + j) % 3];
    for (size_t g = 0; g < groups; ++g, bytes += 4 * sizeof(glm::vec3))
        for (int k = 0; k < 3; ++k) {
            Lanes x;
            std::memcpy(&x, bytes + k * sizeof x, sizeof x);
            nonfinite += x - x;
            lo[k] = x < lo[k] ? x : lo[k], hi[k] = hi[k] < x ? x : hi[k];
        }
    if (!lanes::all(nonfinite == 0.0f)) return false;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 4; ++j) {
            const int axis = (4 * k + j) % 3;
            out.lo[axis] = std::min(out.lo[axis], lo[k][j]), out.hi[axis] = std::max(out.hi[axis], hi[k][j]);
        }
    return true;
}

}  // namespace

PositionBounds position_bounds(const std::vector<glm::vec3>& positions) {
    constexpr size_t kBlock = 65536;  // a multiple of 4
    const size_t n = positions.size();
    std::vector<PositionBounds> blocks((n + kBlock - 1) / kBlock);
    parallel_for_chunked(
        blocks.size(),
        [&](size_t b) {
            const size_t first = b * kBlock, last = std::min(n, first + kBlock), groups = (last - first) / 4;
            PositionBounds out;
            if (!add_groups(out, positions.data(), first, groups)) add_points(out, positions.data(), first, first + 4 * groups);
            add_points(out, positions.data(), first + 4 * groups, last);
            blocks[b] = out;
        },
        1);
    PositionBounds all;
    for (const PositionBounds& b : blocks) all.lo = glm::min(all.lo, b.lo), all.hi = glm::max(all.hi, b.hi);
    return all;
}

}  // namespace kappa
