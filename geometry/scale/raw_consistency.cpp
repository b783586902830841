#include "raw_consistency.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kappa {

namespace {

constexpr double kRatio = 2.0;
constexpr size_t kSamples = 65536;  // at most about this many vertices are compared

}  // namespace

namespace {

size_t sample_stride(const Mesh& mesh) { return std::max<size_t>(1, mesh.vertex_count() / kSamples); }

}  // namespace

bool consistency_testable(const ScaleSpace& space, const SurfaceFields& raw) {
    return space.levels.size() >= 2 && raw.has_curvature();
}

// Every stride-th vertex: the levels' fields are evaluated there alone
// (a scale of 0 keeps the raw fields, at no cost).
std::vector<float> consistency_scales(const Mesh& mesh, const ScaleSpace& space, size_t level) {
    std::vector<float> scales(mesh.vertex_count(), 0.0f);
    for (size_t v = 0; v < scales.size(); v += sample_stride(mesh)) scales[v] = space.level_scale(level);
    return scales;
}

RawConsistency judge_consistency(const Mesh& mesh, const SurfaceFields& raw, const SurfaceFields& first,
                                 const SurfaceFields& second) {
    RawConsistency out;
    double step0 = 0, step1 = 0;
    size_t n = 0;
    for (size_t v = 0; v < mesh.vertex_count(); v += sample_stride(mesh)) {  // serial: the same sums for any thread count
        if (raw.unreliable(v)) continue;
        const double c_raw = dcurv_norm(glm::dvec4(raw.dcurv[v])), c0 = dcurv_norm(glm::dvec4(first.dcurv[v])),
                     c1 = dcurv_norm(glm::dvec4(second.dcurv[v]));
        if (!std::isfinite(c_raw) || !std::isfinite(c0) || !std::isfinite(c1)) continue;
        step0 += (c_raw - c0) * (c_raw - c0);
        step1 += (c0 - c1) * (c0 - c1);
        ++n;
    }
    if (n == 0) return out;
    out.raw_to_first = std::sqrt(step0 / double(n));
    out.first_to_second = std::sqrt(step1 / double(n));
    out.consistent = !(out.raw_to_first > kRatio * out.first_to_second);
    return out;
}

RawConsistency raw_dcurv_consistency(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw) {
    if (!consistency_testable(space, raw)) return {};
    const SurfaceFields first = fields_at_scale(mesh, space, raw, consistency_scales(mesh, space, 0)),
                        second = fields_at_scale(mesh, space, raw, consistency_scales(mesh, space, 1));
    return judge_consistency(mesh, raw, first, second);
}

}  // namespace kappa
