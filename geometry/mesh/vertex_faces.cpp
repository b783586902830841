#include "vertex_faces.h"

#include "geometry/io/prefault.h"
#include "geometry/parallel/parallel.h"

#include <algorithm>

namespace kappa {

// A counting sort of the corners by vertex, split over contiguous ranges of
// faces: each range counts its own corners per vertex, then the counts give
// every (range, vertex) pair its own stretch of the vertex's row, ranges in
// order, so each range scatters its corners independently and the rows come
// out in face order whatever the number of ranges.
VertexFaces build_vertex_faces(const Mesh& mesh) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    VertexFaces vf;
    // One count array per range: few ranges (memory nv * 4 bytes each), and
    // one when there is too little to share.
    const size_t ranges = std::min<size_t>({thread_count(), 4, std::max<size_t>(1, nf / 65536)});
    const size_t per_range = (nf + ranges - 1) / ranges;
    std::vector<std::vector<uint32_t>> counts(ranges);
    parallel_for_ranges(
        ranges,
        [&](size_t first, size_t last) {
            for (size_t r = first; r < last; ++r) {
                std::vector<uint32_t>& count = counts[r];
                io::reserve_prefaulted(count, nv);
                count.assign(nv, 0);
                const size_t f_end = std::min(nf, (r + 1) * per_range);
                for (size_t f = r * per_range; f < f_end; ++f)
                    for (int j = 0; j < 3; ++j) ++count[mesh.faces[f][j]];
            }
        },
        1);

    // Row starts, then each range's start within each row (in place of its counts).
    io::reserve_prefaulted(vf.offsets, row_starts_room(nv));
    vf.offsets.resize(nv + 1);
    uint32_t total = 0;
    for (size_t v = 0; v < nv; ++v) {
        vf.offsets[v] = total;
        for (auto& count : counts) {
            const uint32_t n = count[v];
            count[v] = total;
            total += n;
        }
    }
    vf.offsets[nv] = total;

    io::reserve_prefaulted(vf.corners, 3 * nf);
    vf.corners.resize(3 * nf);
    parallel_for_ranges(
        ranges,
        [&](size_t first, size_t last) {
            for (size_t r = first; r < last; ++r) {
                std::vector<uint32_t>& fill = counts[r];
                const size_t f_end = std::min(nf, (r + 1) * per_range);
                for (size_t f = r * per_range; f < f_end; ++f)
                    for (int j = 0; j < 3; ++j) vf.corners[fill[mesh.faces[f][j]]++] = uint32_t(3 * f + j);
            }
        },
        1);
    return vf;
}

}  // namespace kappa
