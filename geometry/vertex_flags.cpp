#include "vertex_flags.h"

#include "parallel.h"
#include "prefetch.h"

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

// The common case, an interior vertex of a consistently oriented manifold:
// the far ends reached going forward around each face (corner j -> j + 1)
// and those reached going backward (j -> j + 2) match one to one. Then every
// end is used by exactly two faces and there is nothing to flag. True only
// when that holds (a degree-d fan costs d^2 comparisons instead of (2d)^2);
// otherwise the caller counts the edge uses in full.
bool closed_manifold_fan(const uint32_t* forward, const uint32_t* backward, size_t d) {
    for (size_t a = 0; a < d; ++a) {
        size_t fwd_matches = 0, bwd_matches = 0;
        for (size_t b = 0; b < d; ++b) {
            fwd_matches += forward[a] == backward[b];
            bwd_matches += backward[a] == forward[b];
        }
        if (fwd_matches != 1 || bwd_matches != 1) return false;
    }
    return true;
}

}  // namespace

std::vector<uint8_t> compute_vertex_flags(const Mesh& mesh, const VertexFaces& vf,
                                          const std::vector<float>& point_areas) {
    std::vector<uint8_t> flags(mesh.vertex_count(), 0);
    parallel_for_ranges(mesh.vertex_count(), [&](size_t first, size_t last) {
        constexpr size_t kSmallFan = 32;
        uint32_t forward[kSmallFan], backward[kSmallFan];
        std::vector<uint32_t> ends;
        for (size_t v = first; v < last; ++v) {
            const uint8_t degenerate = point_areas[v] > 0 ? 0 : kFlagDegenerate;
            const size_t d = vf.degree(v);
            if (d == 0) {
                flags[v] = kFlagIsolated;
                continue;
            }
            if (d <= kSmallFan) {
                bool self_edge = false;  // a face that uses v twice: count in full
                for (size_t k = 0; k < d; ++k) {
                    const uint32_t c = vf.corners[vf.begin(v) + k];
                    prefetch_face_ahead(vf, vf.begin(v) + k, mesh.faces.data());
                    const Face& f = mesh.faces[c / 3];
                    forward[k] = f[(c % 3 + 1) % 3];
                    backward[k] = f[(c % 3 + 2) % 3];
                    self_edge |= forward[k] == v || backward[k] == v;
                }
                if (!self_edge && closed_manifold_fan(forward, backward, d)) {
                    flags[v] = degenerate;
                    continue;
                }
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
            flags[v] = degenerate | edge_use_flags(ends.data(), ends.size());
        }
    });
    return flags;
}

}  // namespace kappa
