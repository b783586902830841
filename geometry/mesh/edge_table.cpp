#include "edge_table.h"

#include "geometry/io/prefault.h"
#include "geometry/parallel/parallel.h"

#include <algorithm>

namespace kappa {

void sort_short_run(uint64_t* begin, uint64_t* end) {
    if (end - begin < 2) return;
    if (end - begin > 32) {
        std::sort(begin, end);
        return;
    }
    for (uint64_t* i = begin + 1; i < end; ++i) {
        const uint64_t key = *i;
        uint64_t* j = i;
        for (; j > begin && *(j - 1) > key; --j) *j = *(j - 1);
        *j = key;
    }
}

namespace {

// Large buffers are mapped in one call: page faults on first touch cost more
// than the work on some machines (see io/prefault.h).
template <typename T>
void resize_prefaulted(std::vector<T>& v, size_t n) {
    io::reserve_prefaulted(v, n);
    v.resize(n);
}

uint32_t other_vertex(uint64_t key) { return uint32_t(key >> 32); }

}  // namespace

EdgeTable build_edge_table(const Mesh& mesh) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    EdgeTable t;

    // Bucket of each half-edge: its smaller vertex.
    std::vector<uint32_t> offset;
    resize_prefaulted(offset, nv + 1);
    for (const Face& f : mesh.faces)
        if (is_valid_face(f, nv))
            for (int i = 0; i < 3; ++i) ++offset[std::min(f[i], f[(i + 1) % 3]) + 1];
    for (size_t v = 0; v < nv; ++v) offset[v + 1] += offset[v];

    // Key in a bucket: larger vertex (high 32 bits), then half-edge id, so
    // sorting a bucket groups each edge's half-edges in face order.
    std::vector<uint64_t> keys;
    resize_prefaulted(keys, offset[nv]);
    {
        std::vector<uint32_t> fill(offset.begin(), offset.end() - 1);
        for (size_t fi = 0; fi < nf; ++fi) {
            const Face& f = mesh.faces[fi];
            if (!is_valid_face(f, nv)) continue;
            for (int i = 0; i < 3; ++i) {
                const uint32_t a = f[i], b = f[(i + 1) % 3];
                keys[fill[std::min(a, b)]++] = (uint64_t(std::max(a, b)) << 32) | uint64_t(3 * fi + i);
            }
        }
    }

    // Sort each bucket and count its distinct edges; then number the edges
    // (prefix sum) and write them, each vertex's bucket independently.
    std::vector<uint32_t> edge_start;
    resize_prefaulted(edge_start, nv + 1);
    parallel_for_ranges(nv, [&](size_t first, size_t last) {
        for (size_t v = first; v < last; ++v) {
            sort_short_run(keys.data() + offset[v], keys.data() + offset[v + 1]);
            uint32_t distinct = 0;
            for (uint32_t k = offset[v]; k < offset[v + 1]; ++k)
                distinct += k == offset[v] || other_vertex(keys[k]) != other_vertex(keys[k - 1]);
            edge_start[v + 1] = distinct;
        }
    });
    for (size_t v = 0; v < nv; ++v) edge_start[v + 1] += edge_start[v];

    const size_t edges = edge_start[nv];
    resize_prefaulted(t.ends, edges);
    resize_prefaulted(t.first, edges + 1);
    resize_prefaulted(t.halfedges, keys.size());
    parallel_for_ranges(nv, [&](size_t first, size_t last) {
        for (size_t v = first; v < last; ++v) {
            uint32_t e = edge_start[v];
            for (uint32_t k = offset[v]; k < offset[v + 1]; ++k) {
                if (k == offset[v] || other_vertex(keys[k]) != other_vertex(keys[k - 1])) {
                    t.ends[e] = {uint32_t(v), other_vertex(keys[k])};
                    t.first[e++] = k;
                }
                t.halfedges[k] = uint32_t(keys[k]);
            }
        }
    });
    t.first[edges] = uint32_t(keys.size());
    return t;
}

}  // namespace kappa
