#include "chain.h"

#include <glm/vec2.hpp>

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
    // Each end (segment * 2 + side) belongs to a point, found in an
    // open-addressing table on its position's bits; a path goes on through a
    // point only where exactly two ends meet, so each point keeps its number
    // of ends and its first two.
    const size_t n = segments.size(), ne = 2 * n;
    // Scratch kept per thread: the CPU line pass chains a few segments at a
    // time, thousands of times a frame.
    thread_local std::vector<uint32_t> table, end_point, degree;
    thread_local std::vector<glm::uvec2> two_ends;
    thread_local std::vector<PointKey> point_keys;
    thread_local std::vector<char> used;
    size_t capacity = 16;
    while (capacity < 2 * ne) capacity *= 2;
    table.assign(capacity, 0);  // point + 1; 0: empty
    point_keys.clear(), degree.clear(), two_ends.clear();
    end_point.resize(ne);
    for (size_t e = 0; e < ne; ++e) {
        const PointKey k = key_of(e % 2 ? segments[e / 2].b : segments[e / 2].a);
        uint64_t h = uint64_t(k.x) * 0x9E3779B97F4A7C15ull + uint64_t(k.y) * 0xC2B2AE3D27D4EB4Full +
                     uint64_t(k.z) * 0x165667B19E3779F9ull;
        h ^= h >> 29;
        size_t slot = size_t(h) & (capacity - 1);
        while (table[slot] != 0 && !(point_keys[table[slot] - 1] == k)) slot = (slot + 1) & (capacity - 1);
        if (table[slot] == 0) {
            point_keys.push_back(k), degree.push_back(0), two_ends.emplace_back(0);
            table[slot] = uint32_t(point_keys.size());
        }
        const uint32_t p = table[slot] - 1;
        end_point[e] = p;
        if (degree[p] < 2) two_ends[p][int(degree[p])] = uint32_t(e);
        ++degree[p];
    }
    // The other end at the same point, when the point joins exactly two ends.
    auto partner = [&](size_t e) -> long {
        const uint32_t p = end_point[e];
        if (degree[p] != 2) return -1;
        return long(two_ends[p].x == e ? two_ends[p].y : two_ends[p].x);
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
