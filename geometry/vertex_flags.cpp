#include "vertex_flags.h"

#include "parallel.h"

#include <algorithm>
#include <utility>

namespace kappa {

std::vector<uint8_t> compute_vertex_flags(const Mesh& mesh, const VertexFaces& vf,
                                          const std::vector<float>& point_areas) {
    std::vector<uint8_t> flags(mesh.vertex_count(), 0);
    parallel_for_ranges(mesh.vertex_count(), [&](size_t first, size_t last) {
        std::vector<uint32_t> ends;  // far ends of the edges at v, one entry per face using the edge
        for (size_t v = first; v < last; ++v) {
            if (vf.degree(v) == 0) {
                flags[v] = kFlagIsolated;
                continue;
            }
            uint8_t fl = point_areas[v] > 0 ? 0 : kFlagDegenerate;
            ends.clear();
            for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
                const uint32_t c = vf.corners[k];
                const Face& f = mesh.faces[c / 3];
                for (int s = 1; s <= 2; ++s) {
                    const uint32_t w = f[(c % 3 + s) % 3];
                    if (w != v) ends.push_back(w);
                }
            }
            std::sort(ends.begin(), ends.end());
            for (size_t a = 0; a < ends.size();) {
                size_t b = a;
                while (b < ends.size() && ends[b] == ends[a]) ++b;
                if (b - a == 1) fl |= kFlagBoundary;
                if (b - a > 2) fl |= kFlagNonManifold;
                a = b;
            }
            flags[v] = fl;
        }
    });
    return flags;
}

}  // namespace kappa
