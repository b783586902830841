#include "vertex_flags.h"

#include "parallel.h"

#include <algorithm>

namespace kappa {

namespace {

// Boundary / non-manifold bits from the far ends of the edges at a vertex,
// one entry per (face, edge) use: an end seen once is a boundary edge, more
// than twice a non-manifold edge. Small fans (the common case) are counted by
// direct comparison, large ones by sorting.
uint8_t edge_use_flags(uint32_t* ends, size_t n) {
    uint8_t fl = 0;
    if (n <= 64) {
        for (size_t a = 0; a < n; ++a) {
            size_t count = 0;
            for (size_t b = 0; b < n; ++b) count += ends[b] == ends[a];
            if (count == 1) fl |= kFlagBoundary;
            if (count > 2) fl |= kFlagNonManifold;
        }
        return fl;
    }
    std::sort(ends, ends + n);
    for (size_t a = 0; a < n;) {
        size_t b = a;
        while (b < n && ends[b] == ends[a]) ++b;
        if (b - a == 1) fl |= kFlagBoundary;
        if (b - a > 2) fl |= kFlagNonManifold;
        a = b;
    }
    return fl;
}

}  // namespace

std::vector<uint8_t> compute_vertex_flags(const Mesh& mesh, const VertexFaces& vf,
                                          const std::vector<float>& point_areas) {
    std::vector<uint8_t> flags(mesh.vertex_count(), 0);
    parallel_for_ranges(mesh.vertex_count(), [&](size_t first, size_t last) {
        std::vector<uint32_t> ends;
        for (size_t v = first; v < last; ++v) {
            if (vf.degree(v) == 0) {
                flags[v] = kFlagIsolated;
                continue;
            }
            ends.clear();
            for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
                const uint32_t c = vf.corners[k];
                const Face& f = mesh.faces[c / 3];
                for (int s = 1; s <= 2; ++s) {
                    const uint32_t w = f[(c % 3 + s) % 3];
                    if (w != v) ends.push_back(w);
                }
            }
            flags[v] = (point_areas[v] > 0 ? 0 : kFlagDegenerate) | edge_use_flags(ends.data(), ends.size());
        }
    });
    return flags;
}

}  // namespace kappa
