#include "render/surface/colormap.h"

#include "geometry/parallel/select_value.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kappa::render {

float colormap_scalar(ColorMap map, const SurfaceFields& f, size_t i) {
    const float k1 = f.k1[i], k2 = f.k2[i];
    switch (map) {
        case ColorMap::K1: return k1;
        case ColorMap::K2: return k2;
        case ColorMap::Mean: return 0.5f * (k1 + k2);
        case ColorMap::Gaussian: return k1 * k2;
        case ColorMap::Principal: return std::max(std::abs(k1), std::abs(k2));
        case ColorMap::DCurv: return dcurv_norm(f.dcurv[i]);
        case ColorMap::None: break;
    }
    return 0;
}

float robust_range(ColorMap map, const SurfaceFields& fields, float percentile) {
    if (map == ColorMap::None || fields.k1.empty()) return 1;
    // |value| at each vertex: the reliable vertices' finite ones, else (none
    // reliable) every finite one; -1 leaves a vertex out.
    const auto values = [&](bool reliable_only) {
        return [&fields, map, reliable_only](size_t i) {
            if (reliable_only && fields.unreliable(i)) return -1.0f;
            const float v = std::abs(colormap_scalar(map, fields, i));
            return std::isfinite(v) ? v : -1.0f;
        };
    };
    const auto rank = [percentile](size_t m) {
        return std::min(m - 1, size_t(std::clamp(percentile, 0.0f, 1.0f) * float(m)));
    };
    bool reliable_only = true;
    float r = select_nonnegative(fields.k1.size(), values(true), rank);
    if (std::isnan(r)) r = select_nonnegative(fields.k1.size(), values(reliable_only = false), rank);
    if (std::isnan(r)) return 1;
    if (r > 0) return r;
    // Mostly flat: fall back to the largest value, or 1 when all are zero.
    const float mx = select_nonnegative(fields.k1.size(), values(reliable_only), [](size_t m) { return m - 1; });
    return mx > 0 ? mx : 1.0f;
}

}  // namespace kappa::render
