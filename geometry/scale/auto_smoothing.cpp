#include "auto_smoothing.h"

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

constexpr float kNoiseFloor = 0.003f;    // relative noise below which nothing is smoothed
constexpr float kReferenceNoise = 0.02f; // the noise level the constants below are measured at
constexpr float kNormals = 2.0f, kCurvature = 1.5f, kDcurv = 3.0f;  // widths at the reference, in edges

}  // namespace

SmoothingOptions choose_smoothing_widths(const NoiseLevel& noise) {
    SmoothingOptions out;
    const float excess = noise.relative - kNoiseFloor;
    if (!(excess > 0) || !(noise.median_edge > 0)) return out;
    const float h = noise.median_edge * std::pow(excess / kReferenceNoise, 0.25f);
    out.normals = kNormals * h;
    out.curvature = kCurvature * h;
    out.dcurv = kDcurv * h;
    return out;
}

}  // namespace kappa
