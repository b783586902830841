#include "face_survey.h"

#include "crease_candidates.h"
#include "creases.h"
#include "edge_table.h"

#include "geometry/parallel/parallel.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace kappa {

FaceSurvey survey_faces(const Mesh& mesh, float crease_angle_deg) {
    FaceSurvey out;
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    if (nv == 0 || nf == 0) return out;
    const glm::dvec3 centroid = vertex_centroid(mesh);
    std::optional<CreaseCandidates> candidates;
    constexpr size_t kBlock = 65536;  // faces; block sums joined in order: independent of the thread count
    constexpr size_t kAhead = 16;     // faces
    std::vector<EnclosedVolumes> partial((nf + kBlock - 1) / kBlock);
    if (crease_angle_deg > 0) candidates.emplace(nv, crease_angle_deg);
    parallel_for_chunks(
        partial.size(),
        [&](size_t first, size_t last) {
            for (size_t b = first; b < last; ++b) {
                double signed_sum = 0, unsigned_sum = 0;
                const size_t end = std::min(nf, (b + 1) * kBlock);
                for (size_t f = b * kBlock; f < end; ++f) {
                    // The corners of a face some way ahead, fetched early: they lie all over memory.
                    if (f + kAhead < end)
                        for (int k = 0; k < 3; ++k)
                            if (const uint32_t v = mesh.faces[f + kAhead][k]; v < nv) {
                                __builtin_prefetch(&mesh.positions[v]);
                                if (candidates) candidates->prefetch(v);
                            }
                    const Face& face = mesh.faces[f];
                    const double v = tetrahedron_volume6(mesh, face, centroid);
                    signed_sum += v, unsigned_sum += std::fabs(v);
                    if (candidates && is_valid_face(face, nv)) candidates->add_face(face, face_cross(mesh, face));
                }
                partial[b] = {signed_sum, unsigned_sum};
            }
        },
        1);
    for (const EnclosedVolumes& p : partial)
        out.volumes.signed_sum += p.signed_sum, out.volumes.unsigned_sum += p.unsigned_sum;
    if (candidates) out.crease_candidates = candidates->vertices();
    return out;
}

std::vector<uint32_t> crease_candidates(const Mesh& mesh, float angle_deg) {
    return survey_faces(mesh, angle_deg).crease_candidates;
}

}  // namespace kappa
