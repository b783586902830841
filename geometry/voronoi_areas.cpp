#include "voronoi_areas.h"

#include "parallel.h"
#include "prefetch.h"

namespace kappa {

std::vector<float> compute_point_areas(const VertexFaces& vf, const std::vector<glm::vec3>& corner_areas) {
    const size_t nv = vf.offsets.size() - 1;
    std::vector<float> areas(nv);
    parallel_for(nv, [&](size_t v) {
        double sum = 0;
        for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
            const uint32_t c = vf.corners[k];
            prefetch_face_ahead(vf, k, corner_areas.data());
            sum += corner_areas[c / 3][c % 3];
        }
        areas[v] = float(sum);
    });
    return areas;
}

}  // namespace kappa
