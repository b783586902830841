#include "raw_consistency.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kappa {

namespace {

constexpr double kRatio = 2.0;
constexpr size_t kSamples = 65536;  // at most about this many vertices are compared

}  // namespace

RawConsistency raw_dcurv_consistency(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw) {
    RawConsistency out;
    if (space.levels.size() < 2 || !raw.has_curvature()) return out;
    // Every stride-th vertex: the levels' fields are evaluated there alone
    // (a scale of 0 keeps the raw fields, at no cost).
    const size_t stride = std::max<size_t>(1, mesh.vertex_count() / kSamples);
    auto at_sampled = [&](float sigma) {
        std::vector<float> scales(mesh.vertex_count(), 0.0f);
        for (size_t v = 0; v < scales.size(); v += stride) scales[v] = sigma;
        return fields_at_scale(mesh, space, raw, scales);
    };
    const SurfaceFields first = at_sampled(space.level_scale(0)), second = at_sampled(space.level_scale(1));
    double step0 = 0, step1 = 0;
    size_t n = 0;
    for (size_t v = 0; v < mesh.vertex_count(); v += stride) {  // serial: the same sums for any thread count
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

}  // namespace kappa
