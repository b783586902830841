#include "chain.h"

#include <algorithm>
#include <cstring>
#include <tuple>
#include <utility>

namespace kappa {

namespace {

struct PointKey {
    uint32_t x, y, z;
    bool operator==(const PointKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

PointKey key_of(glm::vec3 p) {
    if (p.x == 0) p.x = 0;  // -0 and 0 are one point
    if (p.y == 0) p.y = 0;
    if (p.z == 0) p.z = 0;
    PointKey k;
    std::memcpy(&k.x, &p.x, 4), std::memcpy(&k.y, &p.y, 4), std::memcpy(&k.z, &p.z, 4);
    return k;
}

}  // namespace

std::vector<Polyline> chain_segments(const std::vector<LineSegment>& segments) {
    // Each end (segment * 2 + side) belongs to a point; ends of a point are
    // listed together, in end order. Points are found by sorting the ends by
    // their position's bits (no hash table: cheaper for the short lists of
    // one block of a frame, and the same result).
    const size_t n = segments.size();
    // Scratch kept per thread: the CPU line pass chains a few segments at a
    // time, thousands of times a frame.
    thread_local std::vector<std::pair<PointKey, uint32_t>> sorted;
    thread_local std::vector<uint32_t> end_point, first, ends;
    thread_local std::vector<char> used;
    sorted.resize(2 * n);
    for (size_t e = 0; e < 2 * n; ++e) sorted[e] = {key_of(e % 2 ? segments[e / 2].b : segments[e / 2].a), uint32_t(e)};
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) {
        return std::tie(a.first.x, a.first.y, a.first.z, a.second) < std::tie(b.first.x, b.first.y, b.first.z, b.second);
    });
    end_point.resize(2 * n), ends.resize(2 * n);
    first.clear();
    for (size_t i = 0; i < sorted.size(); ++i) {
        if (i == 0 || !(sorted[i].first == sorted[i - 1].first)) first.push_back(uint32_t(i));
        end_point[sorted[i].second] = uint32_t(first.size() - 1);
        ends[i] = sorted[i].second;
    }
    first.push_back(uint32_t(sorted.size()));
    auto degree = [&](uint32_t p) { return first[p + 1] - first[p]; };
    // The other end at the same point, when the point joins exactly two ends.
    auto partner = [&](size_t e) -> long {
        const uint32_t p = end_point[e];
        if (degree(p) != 2) return -1;
        const uint32_t a = ends[first[p]], b = ends[first[p] + 1];
        return long(a == e ? b : a);
    };

    used.assign(n, 0);
    std::vector<Polyline> out;
    // Walks from segment s, entering at end `in`, appending points, until a path end.
    auto walk = [&](size_t s, int in_side, Polyline& line) {
        for (;;) {
            used[s] = 1;
            const LineSegment& seg = segments[s];
            const int out_side = 1 - in_side;
            line.points.push_back(out_side ? seg.b : seg.a);
            line.opacity.push_back(out_side ? seg.opacity_b : seg.opacity_a);
            line.strength.push_back(out_side ? seg.strength_b : seg.strength_a);
            line.tolerance = std::max(line.tolerance, seg.tolerance);
            const long next = partner(2 * s + size_t(out_side));
            if (next < 0 || used[size_t(next) / 2]) return;
            s = size_t(next) / 2, in_side = int(next % 2);
        }
    };
    auto start_at = [&](size_t s, int in_side) {
        // Grown in scratch kept per thread, then copied at its final size: one
        // allocation per array instead of one per doubling.
        thread_local Polyline line;
        line.points.clear(), line.opacity.clear(), line.strength.clear();
        line.tolerance = Polyline{}.tolerance;
        const LineSegment& seg = segments[s];
        line.points.push_back(in_side ? seg.b : seg.a);
        line.opacity.push_back(in_side ? seg.opacity_b : seg.opacity_a);
        line.strength.push_back(in_side ? seg.strength_b : seg.strength_a);
        walk(s, in_side, line);
        out.push_back(line);
    };
    // Open paths first, from their ends, then what is left (closed loops).
    for (size_t s = 0; s < n; ++s)
        for (int side = 0; side < 2 && !used[s]; ++side)
            if (partner(2 * s + size_t(side)) < 0) start_at(s, side);
    for (size_t s = 0; s < n; ++s)
        if (!used[s]) start_at(s, 0);
    return out;
}

}  // namespace kappa
