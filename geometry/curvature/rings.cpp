#include "rings.h"

#include "geometry/parallel/parallel.h"

#include <algorithm>

namespace kappa {

VertexAdjacency build_vertex_adjacency(const Mesh& mesh, const VertexFaces& vf) {
    const size_t nv = mesh.vertex_count();
    VertexAdjacency adj;
    // Upper bound first (two per incident corner), then compacted per row.
    std::vector<uint32_t> row_end(nv);
    std::vector<uint32_t> scratch(size_t(vf.offsets.back()) * 2);
    parallel_for(nv, [&](size_t v) {
        uint32_t* out = scratch.data() + size_t(vf.begin(v)) * 2;
        uint32_t n = 0;
        for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
            const uint32_t c = vf.corners[k];
            const Face& f = mesh.faces[c / 3];
            const uint32_t a = f[(c + 1) % 3], b = f[(c + 2) % 3];
            if (a != v) out[n++] = a;
            if (b != v) out[n++] = b;
        }
        std::sort(out, out + n);
        row_end[v] = uint32_t(std::unique(out, out + n) - out);
    });
    adj.offsets.resize(nv + 1);
    adj.offsets[0] = 0;
    for (size_t v = 0; v < nv; ++v) adj.offsets[v + 1] = adj.offsets[v] + row_end[v];
    adj.neighbours.resize(adj.offsets[nv]);
    parallel_for(nv, [&](size_t v) {
        std::copy_n(scratch.data() + size_t(vf.begin(v)) * 2, row_end[v], adj.neighbours.data() + adj.offsets[v]);
    });
    return adj;
}

const std::vector<uint32_t>& RingCollector::collect(const VertexAdjacency& adj, uint32_t v, int rings) {
    if (++epoch_ == 0) {  // wrapped: clear the marks
        std::fill(mark_.begin(), mark_.end(), 0);
        epoch_ = 1;
    }
    ring_.clear();
    ring_.push_back(v);
    mark_[v] = epoch_;
    frontier_begin_ = 0;
    rings_ = 0;
    while (rings_ < rings) {
        const size_t before = ring_.size();
        grow(adj);
        if (ring_.size() == before) break;  // the component is exhausted
    }
    return ring_;
}

int RingCollector::grow(const VertexAdjacency& adj) {
    const size_t frontier_end = ring_.size();
    for (size_t i = frontier_begin_; i < frontier_end; ++i) {
        const uint32_t w = ring_[i];
        for (uint32_t k = adj.begin(w); k < adj.end(w); ++k) {
            const uint32_t x = adj.neighbours[k];
            if (mark_[x] == epoch_) continue;
            mark_[x] = epoch_;
            ring_.push_back(x);
        }
    }
    frontier_begin_ = frontier_end;
    return ++rings_;
}

}  // namespace kappa
