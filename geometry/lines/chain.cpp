#include "chain.h"

#include <algorithm>
#include <cstring>
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
    // listed together, in end order. Points are found in an open-addressing
    // table on their position's bits, numbered as first met; a counting sort
    // then lists each point's ends.
    const size_t n = segments.size(), ne = 2 * n;
    // Scratch kept per thread: the CPU line pass chains a few segments at a
    // time, thousands of times a frame.
    thread_local std::vector<uint32_t> table, end_point, first, ends, next_slot;
    thread_local std::vector<PointKey> point_keys;
    thread_local std::vector<char> used;
    size_t capacity = 16;
    while (capacity < 2 * ne) capacity *= 2;
    table.assign(capacity, 0);  // point + 1; 0: empty
    point_keys.clear();
    end_point.resize(ne);
    for (size_t e = 0; e < ne; ++e) {
        const PointKey k = key_of(e % 2 ? segments[e / 2].b : segments[e / 2].a);
        uint64_t h = uint64_t(k.x) * 0x9E3779B97F4A7C15ull + uint64_t(k.y) * 0xC2B2AE3D27D4EB4Full +
                     uint64_t(k.z) * 0x165667B19E3779F9ull;
        h ^= h >> 29;
        size_t slot = size_t(h) & (capacity - 1);
        while (table[slot] != 0 && !(point_keys[table[slot] - 1] == k)) slot = (slot + 1) & (capacity - 1);
        if (table[slot] == 0) point_keys.push_back(k), table[slot] = uint32_t(point_keys.size());
        end_point[e] = table[slot] - 1;
    }
    const size_t points = point_keys.size();
    first.assign(points + 1, 0);
    for (size_t e = 0; e < ne; ++e) ++first[end_point[e] + 1];
    for (size_t p = 0; p < points; ++p) first[p + 1] += first[p];
    next_slot.assign(first.begin(), first.end() - 1);
    ends.resize(ne);
    for (size_t e = 0; e < ne; ++e) ends[next_slot[end_point[e]]++] = uint32_t(e);
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
