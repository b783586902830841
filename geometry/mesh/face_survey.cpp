#include "face_survey.h"

#include "crease_candidates.h"
#include "creases.h"
#include "edge_table.h"

#include "geometry/parallel/double_lanes.h"
#include "geometry/parallel/parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace kappa {

namespace {

// Four faces at once (lanes.h): their cross products (face_cross), volume terms (tetrahedron_volume6) and
// packed directions (CreaseCandidates::pack_direction) in lanes, the same operations as one face's, so the
// same bits; then each face's sums and corners in face order, as one at a time.
struct FaceSums {
    double signed_sum = 0, unsigned_sum = 0;
    void add(double v) { signed_sum += v, unsigned_sum += std::fabs(v); }
};

void survey_one(const Mesh& mesh, size_t f, glm::dvec3 centroid, CreaseCandidates* candidates, FaceSums& sums) {
    const size_t nv = mesh.vertex_count();
    const Face& face = mesh.faces[f];
    if (face[0] >= nv || face[1] >= nv || face[2] >= nv) return;  // no volume, no edges
    const glm::vec3 cross = face_cross(mesh, face);  // one product for both
    sums.add(tetrahedron_volume6(mesh.positions[face[0]], cross, centroid));
    if (candidates && is_valid_face(face, nv)) candidates->add_face(face, cross);
}

void survey_four(const Mesh& mesh, size_t f, glm::dvec3 centroid, CreaseCandidates* candidates, FaceSums& sums) {
    using lanes::Lanes, lanes::Doubles4;
    const Face* faces = &mesh.faces[f];
    const size_t nv = mesh.vertex_count();
    for (int j = 0; j < 4; ++j)
        if (faces[j][0] >= nv || faces[j][1] >= nv || faces[j][2] >= nv) {
            for (int i = 0; i < 4; ++i) survey_one(mesh, f + i, centroid, candidates, sums);
            return;
        }
    auto corner = [&](int k, int axis) {
        const glm::vec3* p = mesh.positions.data();
        return Lanes{p[faces[0][k]][axis], p[faces[1][k]][axis], p[faces[2][k]][axis], p[faces[3][k]][axis]};
    };
    const lanes::Vec3<Lanes> p0{corner(0, 0), corner(0, 1), corner(0, 2)};
    const lanes::Vec3<Lanes> c = lanes::cross(lanes::Vec3<Lanes>{corner(1, 0), corner(1, 1), corner(1, 2)} - p0,
                                              lanes::Vec3<Lanes>{corner(2, 0), corner(2, 1), corner(2, 2)} - p0);
    auto wide = [](Lanes x) { return __builtin_convertvector(x, Doubles4); };
    const lanes::Vec3<Doubles4> apex{Doubles4{} + centroid.x, Doubles4{} + centroid.y, Doubles4{} + centroid.z};
    const Doubles4 volume =
        lanes::dot(lanes::Vec3<Doubles4>{wide(p0.x), wide(p0.y), wide(p0.z)} - apex,
                   lanes::Vec3<Doubles4>{wide(c.x), wide(c.y), wide(c.z)});
    for (int j = 0; j < 4; ++j) sums.add(std::isfinite(volume[j]) ? volume[j] : 0.0);
    if (!candidates) return;
    const Lanes length2 = lanes::dot(c, c);
    // Faces without a normal (length 0 or not finite) are packed as +x, to keep the pack's lanes finite.
    const lanes::Ints4 normal = (length2 > 0.0f) & (length2 <= std::numeric_limits<float>::max());
    const Lanes one = Lanes{} + 1.0f, zero = Lanes{};
    const lanes::Ints4 packed = CreaseCandidates::pack_direction(normal ? c.x : one, normal ? c.y : zero,
                                                                 normal ? c.z : zero);
    for (int j = 0; j < 4; ++j)
        if (is_valid_face(faces[j], nv))
            candidates->add_face(faces[j], {c.x[j], c.y[j], c.z[j]}, length2[j], uint16_t(packed[j]));
}

}  // namespace

FaceSurvey survey_faces(const Mesh& mesh, float crease_angle_deg) {
    FaceSurvey out;
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    if (nv == 0 || nf == 0) return out;
    const glm::dvec3 centroid = vertex_centroid(mesh);
    std::optional<CreaseCandidates> candidates;
    constexpr size_t kBlock = 65536;  // faces; block sums joined in order: independent of the thread count
    constexpr size_t kAhead = 64;     // faces
    std::vector<EnclosedVolumes> partial((nf + kBlock - 1) / kBlock);
    if (crease_angle_deg > 0) candidates.emplace(nv, crease_angle_deg);
    CreaseCandidates* const cc = candidates ? &*candidates : nullptr;
    parallel_for_chunks(
        partial.size(),
        [&](size_t first, size_t last) {
            for (size_t b = first; b < last; ++b) {
                FaceSums sums;
                const size_t begin = b * kBlock, end = std::min(nf, (b + 1) * kBlock);
                size_t f = begin;
                for (; f + 4 <= end; f += 4) {
                    // The corners of faces some way ahead, fetched early: they lie all over memory.
                    for (size_t g = f + kAhead; g < std::min(end, f + kAhead + 4); ++g)
                        for (int k = 0; k < 3; ++k)
                            if (const uint32_t v = mesh.faces[g][k]; v < nv) {
                                __builtin_prefetch(&mesh.positions[v]);
                                if (cc) cc->prefetch(v);
                            }
                    survey_four(mesh, f, centroid, cc, sums);
                }
                for (; f < end; ++f) survey_one(mesh, f, centroid, cc, sums);
                partial[b] = {sums.signed_sum, sums.unsigned_sum};
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
