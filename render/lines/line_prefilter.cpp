#include "render/lines/line_prefilter.h"

#include "geometry/parallel/parallel.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa::render {

namespace {

enum Bit : uint64_t {
    kUnreliable = 1u << 0,
    kContourFront = 1u << 1,     // n.v > 0 with the contour normal
    kKrPositive = 1u << 2,       // kr sin^2(theta) > 0
    kSuggestive = 1u << 3,       // Dw kr fs^2 - s > 0 (suggestive contours; its sign change: dwkr)
    kHighlight = 1u << 4,        // -Dw kr fs^2 - s_h > 0
    kFront = 1u << 5,            // n.v > 0 with the fields' normal
    kGaussPositive = 1u << 6,    // K > 0
    kMeanPositive = 1u << 7,     // H > 0
    kRidgeStrong = 1u << 8,      // |kmax| > rv_threshold / fs
    kApparentStrong = 1u << 9,   // sqrt(q1) fs > ar_threshold
    kKmaxNegative = 1u << 10,
    kKmaxPositive = 1u << 11,
    kPrincipalStrong = 1u << 12, // |(kmax^2 - kmin^2) n.v fs^2| > ph_threshold
    kTmUnsure = 1u << 13,        // a component of tm near zero (or NaN)
    kDmaxUnsure = 1u << 14,      // a component of dmax near zero, or v.dmax zero (or NaN)
    kVDmaxPositive = 1u << 15,   // v.dmax > 0, dmax turned (see turned_dmax_signs)
};
constexpr uint64_t kFacing = uint64_t(1) << 38;  // n.(eye - p) > 0 (faces_eye)
constexpr int kIsophoteShift = 16, kTopoShift = 24;
constexpr int kTmSignShift = 32, kDmaxSignShift = 35;  // three bits each: x > 0, y > 0, z > 0 (then kFacing)

// The signs of v's components as three bits, and whether one is so near zero
// (or NaN) that a product of two could round to zero: two vectors with the
// same bits and neither unsure have a positive dot product, in float too.
uint64_t sign_bits(glm::vec3 v, bool& unsure) {
    constexpr float kSmall = 1e-18f;  // a product of two is above the smallest normal float
    unsure = unsure || !(std::fabs(v.x) >= kSmall) || !(std::fabs(v.y) >= kSmall) || !(std::fabs(v.z) >= kSmall);
    return uint64_t(v.x > 0) | uint64_t(v.y > 0) << 1 | uint64_t(v.z > 0) << 2;
}

// dmax has no sign: -1 where its component of largest magnitude is negative, else 1.
float dmax_turn(glm::vec3 d) {
    const glm::vec3 a = glm::abs(d);
    const float largest = a.x >= a.y && a.x >= a.z ? d.x : (a.y >= a.z ? d.y : d.z);
    return largest < 0 ? -1.0f : 1.0f;
}
constexpr uint32_t kAnyBand = 255;  // too many levels, or a value on a level within rounding: always tested

// How many of the levels first + k step (k < count) lie below v: a level
// line crosses a triangle only where its vertices' bands differ.
uint64_t band(float v, const LevelSet& levels) {
    const float first = levels.first, step = levels.step;
    const int count = levels.count;
    if (count <= 0 || !(step > 0)) return 0;
    if (count >= int(kAnyBand)) return kAnyBand;
    const float x = (v - first) / step;
    if (std::isnan(x)) return kAnyBand;  // always tested
    if (x <= -1.0f) return 0;            // below every level
    if (x >= float(count) + 1.0f) return uint64_t(count);
    // floor(x) and the nearest integer by truncation, x > -1 here (no libm calls: this runs per vertex).
    const int below = x < 0.0f ? -1 : int(x);
    const float frac = x - float(below);
    const int nearest = frac < 0.5f ? below : below + 1;
    if (std::fabs(x - float(nearest)) < 1e-3f && nearest >= 0 && nearest < count) return kAnyBand;
    return uint64_t(std::clamp(below + 1, 0, count));
}

bool bands_differ(uint64_t a, uint64_t b, uint64_t c, int shift) {
    a = (a >> shift) & 255, b = (b >> shift) & 255, c = (c >> shift) & 255;
    return a == kAnyBand || b == kAnyBand || c == kAnyBand || a != b || b != c;
}

}  // namespace

LinePrefilter make_line_prefilter(const Mesh& mesh, const SurfaceFields& fields, const ViewQuantities& view,
                                  const std::vector<ViewRidgeVertex>& ridges, const ViewRidgeOptions& ridge_options,
                                  const LevelValues& levels, const LineExtractionOptions& o, glm::vec3 eye,
                                  const std::vector<uint8_t>& only) {
    LinePrefilter p;
    p.bits.assign(mesh.vertex_count(), 0);
    make_line_prefilter(mesh, fields, view, ridges, ridge_options, levels, o, eye, only, p);
    return p;
}

void make_line_prefilter(const Mesh& mesh, const SurfaceFields& fields, const ViewQuantities& view,
                         const std::vector<ViewRidgeVertex>& ridges, const ViewRidgeOptions& ridge_options,
                         const LevelValues& levels, const LineExtractionOptions& o, glm::vec3 eye,
                         const std::vector<uint8_t>& only, LinePrefilter& p) {
    begin_line_prefilter(mesh.vertex_count(), ridge_options, o, eye, p);
    parallel_for_ranges(mesh.vertex_count(), [&](size_t begin, size_t end) {
        line_prefilter_bits(mesh, fields, view, ridges, levels, only, begin, end, p);
    });
}

void begin_line_prefilter(size_t vertex_count, const ViewRidgeOptions& ridge_options,
                          const LineExtractionOptions& options, glm::vec3 eye, LinePrefilter& p) {
    p.options = options;
    p.eye = eye;
    p.ridge_options = ridge_options;
    p.bits.resize(vertex_count);
}

void line_prefilter_bits(const Mesh& mesh, const SurfaceFields& fields, const ViewQuantities& view,
                         const std::vector<ViewRidgeVertex>& ridges, const LevelValues& levels,
                         const std::vector<uint8_t>& only, size_t begin, size_t end, LinePrefilter& p) {
    const LineExtractionOptions& o = p.options;
    const ViewRidgeOptions& ridge_options = p.ridge_options;
    const size_t n = mesh.vertex_count();
    const bool has_view = view.kr.size() == n, has_ridges = ridges.size() == n;
    const float rv_limit = o.rv_threshold / o.feature_size;
    const bool all = only.size() != n;
    const bool curvature = (o.parabolic || o.mean_zero || o.ridges || o.valleys) && fields.k1.size() == n &&
                           fields.k2.size() == n;
    for (size_t v = begin; v < end; ++v) {
        if (!all && !only[v]) continue;
        uint64_t b = fields.unreliable(v) ? uint64_t(kUnreliable) : 0u;
        if (o.cull_back_faces && glm::dot(fields.normals[v], p.eye - mesh.positions[v]) > 0) b |= kFacing;
        if (has_view) {
            if (view.contour_ndotv[v] > 0) b |= kContourFront;
            if (view.kr[v] > 0) b |= kKrPositive;
            if (view.sc_strength[v] - o.sc_threshold > 0) b |= kSuggestive;
            if (-view.sc_strength[v] - o.sh_threshold > 0) b |= kHighlight;
            if (view.ndotv[v] > 0) b |= kFront;
        }
        if (curvature) {
            const float k1 = fields.k1[v], k2 = fields.k2[v];
            if (k1 * k2 > 0) b |= kGaussPositive;
            if (0.5f * (k1 + k2) > 0) b |= kMeanPositive;
            const float kmax = std::fabs(k1) >= std::fabs(k2) ? k1 : k2;
            if (std::fabs(kmax) - rv_limit > 0) b |= kRidgeStrong;
        }
        if (has_ridges && ridge_options.apparent_ridges) {
            const ViewRidgeVertex& r = ridges[v];
            if (r.view_curv > ridge_options.ar_threshold) b |= kApparentStrong;
            bool tm_unsure = false;
            b |= sign_bits(r.dq1 * r.t1, tm_unsure) << kTmSignShift;  // tm as apparent_ridge computes it
            if (tm_unsure) b |= kTmUnsure;
        }
        if (has_ridges && ridge_options.principal_highlights) {
            const ViewRidgeVertex& r = ridges[v];
            if (r.kmax < 0) b |= kKmaxNegative;
            if (r.kmax > 0) b |= kKmaxPositive;
            if (std::fabs(r.ph_strength) - ridge_options.ph_threshold > 0) b |= kPrincipalStrong;
            const float turn = dmax_turn(r.dmax);
            const float v_dmax = turn * r.v_dmax;
            bool dmax_unsure = !(v_dmax != 0.0f);
            b |= sign_bits(turn * r.dmax, dmax_unsure) << kDmaxSignShift;
            if (v_dmax > 0) b |= kVDmaxPositive;
            if (dmax_unsure) b |= kDmaxUnsure;
        }
        if (levels.isophote.size() == n)
            b |= band(levels.isophote[v], o.isophote_levels) << kIsophoteShift;
        if (levels.height.size() == n)
            b |= band(levels.height[v], o.topo_levels) << kTopoShift;
        p.bits[v] = b;
    }
}

uint8_t LinePrefilter::families_on(const Face& t, uint8_t wanted) const {
    const uint64_t a = bits[t[0]], b = bits[t[1]], c = bits[t[2]];
    const uint64_t any = a | b | c, differ = any & ~(a & b & c);
    const bool reliable = !(any & kUnreliable);
    const LineExtractionOptions& o = options;
    uint8_t families = 0;
    if (wanted & kViewLines) {
        const bool suggestive_kinds =
            reliable && (any & kFront) &&
            ((o.suggestive && (differ & kKrPositive) && (any & kSuggestive)) ||
             (o.suggestive_highlights && (differ & kKrPositive) && (any & kHighlight)) || (o.dwkr && (differ & kSuggestive)));
        if ((o.contours && (differ & kContourFront)) || suggestive_kinds) families |= kViewLines;
    }
    // Contours only on a triangle turned away at all three corners (cull_back_faces).
    if (o.cull_back_faces && !(any & kFacing)) wanted &= kViewLines;
    if ((wanted & kCurvatureLines) && reliable &&
        ((o.parabolic && (differ & kGaussPositive)) || (o.mean_zero && (differ & kMeanPositive)) ||
         ((o.ridges || o.valleys) && (any & kRidgeStrong))))
        families |= kCurvatureLines;
    constexpr uint64_t tm_signs = uint64_t(7) << kTmSignShift, dmax_signs = uint64_t(7) << kDmaxSignShift;
    if ((wanted & kViewRidges) && reliable &&
        ((ridge_options.apparent_ridges && (any & kApparentStrong) && ((any & kTmUnsure) || (differ & tm_signs))) ||
         (ridge_options.principal_highlights && !((any & kKmaxNegative) && (any & kKmaxPositive)) && (any & kPrincipalStrong) &&
          ((any & kDmaxUnsure) || (differ & (dmax_signs | kVDmaxPositive))))))
        families |= kViewRidges;
    if ((wanted & kIsophotes) && bands_differ(a, b, c, kIsophoteShift)) families |= kIsophotes;
    if ((wanted & kTopo) && bands_differ(a, b, c, kTopoShift)) families |= kTopo;
    return families;
}

}  // namespace kappa::render
