#include "vertex_basics.h"

#include "geometry/parallel/parallel.h"
#include "geometry/parallel/prefetch.h"
#include "vertex_flags.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

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

// Flags of vertex v from the far ends of its d faces' edges (forward[k] and
// backward[k] for its k-th face); `ends` is scratch.
uint8_t fan_flags(uint32_t v, const uint32_t* forward, const uint32_t* backward, size_t d,
                  std::vector<uint32_t>& ends) {
    constexpr size_t kSmallFan = 32;  // above: straight to the full count
    bool self_edge = false;           // a face that uses v twice: count in full
    for (size_t k = 0; k < d; ++k) self_edge |= forward[k] == v || backward[k] == v;
    if (d <= kSmallFan && !self_edge && closed_manifold_fan(forward, backward, d)) return 0;
    ends.clear();
    for (size_t k = 0; k < d; ++k) {
        if (forward[k] != v) ends.push_back(forward[k]);
        if (backward[k] != v) ends.push_back(backward[k]);
    }
    return edge_use_flags(ends.data(), ends.size());
}

}  // namespace

VertexBasics compute_vertex_basics(const VertexFaces& vf, const FaceGeometry& faces) {
    const size_t nv = vf.offsets.size() - 1;
    VertexBasics out;
    out.point_areas.resize(nv);
    out.flags.resize(nv);
    out.normals.resize(nv);
    parallel_for_chunks(nv, [&](size_t first, size_t last) {
        std::vector<uint32_t> forward, backward, ends;
        for (size_t v = first; v < last; ++v) {
            const size_t d = vf.degree(v);
            if (forward.size() < d) {
                forward.resize(d);
                backward.resize(d);
            }
            double area = 0;
            glm::dvec3 normal_sum(0.0);
            for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
                const uint32_t c = vf.corners[k], j = c % 3;
                prefetch_face_ahead(vf, k, faces.records.data());
                const FaceRecord& face = faces.records[c / 3];
                area += face.weights[j];
                // The two edges at corner j are those opposite the other two corners.
                const glm::vec3 il2 = face.inv_edge_len2();
                normal_sum += glm::dvec3(face.area_normal()) * (double(il2[(j + 1) % 3]) * il2[(j + 2) % 3]);
                const Face ids = face.face();
                forward[k - vf.begin(v)] = ids[(j + 1) % 3];
                backward[k - vf.begin(v)] = ids[(j + 2) % 3];
            }
            out.point_areas[v] = float(area);
            const double len = glm::length(normal_sum);
            out.normals[v] = len > 0 && std::isfinite(len) ? glm::vec3(normal_sum / len) : glm::vec3(0.0f);
            if (d == 0) {
                out.flags[v] = kFlagIsolated;
                continue;
            }
            const uint8_t degenerate = out.point_areas[v] > 0 ? 0 : kFlagDegenerate;
            out.flags[v] = degenerate | fan_flags(uint32_t(v), forward.data(), backward.data(), d, ends);
        }
    });
    return out;
}

}  // namespace kappa
