#include "orientation.h"

#include "face_survey.h"

#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace kappa {

glm::dvec3 vertex_centroid(const Mesh& mesh) {
    const size_t n = mesh.positions.size();
    if (n == 0) return glm::dvec3(0.0);
    constexpr size_t kBlock = 65536;  // block sums joined in order: independent of the thread count
    std::vector<glm::dvec3> partial((n + kBlock - 1) / kBlock, glm::dvec3(0.0));
    parallel_for_chunks(
        partial.size(),
        [&](size_t first, size_t last) {
            for (size_t b = first; b < last; ++b) {
                glm::dvec3 sum(0.0);  // in a register, not stored at every point
                for (size_t v = b * kBlock; v < std::min(n, (b + 1) * kBlock); ++v) sum += glm::dvec3(mesh.positions[v]);
                partial[b] = sum;
            }
        },
        1);
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& p : partial) sum += p;
    return sum / double(n);
}

EnclosedVolumes enclosed_volumes(const Mesh& mesh) {
    return survey_faces(mesh, VertexFaces{}, 0).volumes;  // at angle 0 no rows are read
}

bool is_inside_out(const EnclosedVolumes& v) { return v.unsigned_sum > 0 && v.signed_sum < -0.5 * v.unsigned_sum; }

bool is_inside_out(const Mesh& mesh) { return is_inside_out(enclosed_volumes(mesh)); }

bool is_outside_out(const EnclosedVolumes& v) { return v.unsigned_sum > 0 && v.signed_sum > 0.5 * v.unsigned_sum; }

bool is_outside_out(const Mesh& mesh) { return is_outside_out(enclosed_volumes(mesh)); }

void flip_faces(Mesh& mesh, VertexFaces* vf) {
    for (Face& f : mesh.faces) std::swap(f[1], f[2]);
    if (!vf || vf->offsets.empty()) return;
    // Corner 1 of each face is now corner 2 and the other way round. Rows stay in face order; only a
    // vertex met twice in one face (a degenerate face) may need its two corners swapped back in order.
    parallel_for(vf->offsets.size() - 1, [&](size_t v) {
        uint32_t* row = vf->corners.data();
        for (uint32_t k = vf->begin(v); k < vf->end(v); ++k) {
            const uint32_t c = row[k];
            row[k] = c % 3 == 0 ? c : c % 3 == 1 ? c + 1 : c - 1;
            for (uint32_t j = k; j > vf->begin(v) && row[j - 1] > row[j]; --j) std::swap(row[j - 1], row[j]);
        }
    });
}

}  // namespace kappa
