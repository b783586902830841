#include "curvature_lines.h"

#include "geometry/lines/zero_crossings.h"

#include <cmath>

namespace kappa {

using namespace lines;

namespace {

void zero_set(const Face& t, const glm::vec3 p[3], const float f[3], std::vector<LineSegment>& out) {
    Crossing c0, c1;
    if (!find_crossings(t, f, c0, c1)) return;
    out.push_back({point_at(c0, p), point_at(c1, p), 1, 1, 1, 1, half_longest_edge(p)});
}

void ridge_or_valley(const Face& t, const glm::vec3 p[3], const SurfaceFields& f, const LineExtractionOptions& o,
                     ExtractedLines& lines) {
    float kmax[3], e[3];
    glm::vec3 dmax[3];
    for (int i = 0; i < 3; ++i) {
        const uint32_t v = t[i];
        const bool first = std::fabs(f.k1[v]) >= std::fabs(f.k2[v]);
        kmax[i] = first ? f.k1[v] : f.k2[v];
        e[i] = first ? f.dcurv[v].x : f.dcurv[v].w;  // C(d1,d1,d1) = a, C(d2,d2,d2) = d
        dmax[i] = first ? f.d1[v] : f.d2[v];
    }
    glm::vec3 d = dmax[0];
    for (int i = 1; i < 3; ++i) {
        const float flip = glm::dot(dmax[i], dmax[0]) < 0 ? -1.0f : 1.0f;
        e[i] *= flip;
        d += flip * dmax[i];
    }
    Crossing x0, x1;
    if (!find_crossings(t, e, x0, x1)) return;
    // The gradient of e over the triangle (linear interpolation).
    const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const float n2 = glm::dot(n, n);
    if (!(n2 > 0)) return;
    const glm::vec3 grad = (e[0] * glm::cross(n, p[2] - p[1]) + e[1] * glm::cross(n, p[0] - p[2]) +
                            e[2] * glm::cross(n, p[1] - p[0])) / n2;
    const float k = (kmax[0] + kmax[1] + kmax[2]) / 3.0f;
    if (k * glm::dot(grad, d) >= 0) return;  // a minimum of |kmax|, not a ridge or valley
    const bool ridge = k > 0;
    if ((ridge && !o.ridges) || (!ridge && !o.valleys)) return;
    // Keep the part where |kmax| > threshold / fs (linear along the segment).
    const float limit = o.rv_threshold / o.feature_size;
    const float g0 = std::fabs(lerp_at(x0, kmax)) - limit, g1 = std::fabs(lerp_at(x1, kmax)) - limit;
    glm::vec2 range(0, 1);
    if (!clip_positive(g0, g1, range)) return;
    const float ramp = std::max(o.rv_threshold, 0.05f) / o.feature_size;
    const float ga = g0 + (g1 - g0) * range.x, gb = g0 + (g1 - g0) * range.y;
    const float a0 = o.fade ? std::clamp(ga / ramp, 0.0f, 1.0f) : 1.0f, a1 = o.fade ? std::clamp(gb / ramp, 0.0f, 1.0f) : 1.0f;
    if (std::max(a0, a1) <= 0) return;
    const glm::vec3 c0 = point_at(x0, p), c1 = point_at(x1, p);
    // Strength: |kmax| fs, the dimensionless value compared with the threshold.
    lines[int(ridge ? LineType::Ridge : LineType::Valley)].push_back(
        {c0 + (c1 - c0) * range.x, c0 + (c1 - c0) * range.y, a0, a1, (ga + limit) * o.feature_size,
         (gb + limit) * o.feature_size, half_longest_edge(p)});
}

}  // namespace

void extract_curvature_lines(const Mesh& mesh, const SurfaceFields& f, const LineExtractionOptions& o,
                             ExtractedLines& lines) {
    if (!(o.parabolic || o.mean_zero || o.ridges || o.valleys)) return;
    for (const Face& t : mesh.faces) curvature_lines_of_face(mesh, t, f, o, lines);
}

void curvature_lines_of_face(const Mesh& mesh, const Face& t, const SurfaceFields& f, const LineExtractionOptions& o,
                             ExtractedLines& lines) {
    {
        if (f.unreliable(t[0]) || f.unreliable(t[1]) || f.unreliable(t[2])) return;
        const glm::vec3 p[3] = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
        if (o.parabolic) {
            const float K[3] = {f.k1[t[0]] * f.k2[t[0]], f.k1[t[1]] * f.k2[t[1]], f.k1[t[2]] * f.k2[t[2]]};
            zero_set(t, p, K, lines[int(LineType::Parabolic)]);
        }
        if (o.mean_zero) {
            const float H[3] = {0.5f * (f.k1[t[0]] + f.k2[t[0]]), 0.5f * (f.k1[t[1]] + f.k2[t[1]]),
                                0.5f * (f.k1[t[2]] + f.k2[t[2]])};
            zero_set(t, p, H, lines[int(LineType::MeanZero)]);
        }
        if (o.ridges || o.valleys) ridge_or_valley(t, p, f, o, lines);
    }
}

}  // namespace kappa
