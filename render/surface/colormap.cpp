#include "render/surface/colormap.h"

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
    std::vector<float> values;
    values.reserve(fields.k1.size());
    for (int pass = 0; pass < 2 && values.empty(); ++pass)
        for (size_t i = 0; i < fields.k1.size(); ++i) {
            const bool reliable = !fields.unreliable(i);
            const float v = std::abs(colormap_scalar(map, fields, i));
            if ((reliable || pass == 1) && std::isfinite(v)) values.push_back(v);
        }
    if (values.empty()) return 1;
    const size_t k = std::min(values.size() - 1, size_t(std::clamp(percentile, 0.0f, 1.0f) * float(values.size())));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    const float r = values[k];
    if (r > 0) return r;
    // Mostly flat: fall back to the largest value, or 1 when all are zero.
    const float mx = *std::max_element(values.begin(), values.end());
    return mx > 0 ? mx : 1.0f;
}

}  // namespace kappa::render
