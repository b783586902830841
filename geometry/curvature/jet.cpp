#include "jet.h"

#include "graph_geometry.h"
#include "normal_equations.h"
#include "rings.h"

#include "geometry/parallel/parallel.h"
#include "geometry/scale/noise_level.h"
#include "tensor_frames.h"
#include "vertex_flags.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

// The moment loops have constant bounds; unrolled they run about twice as fast.
#if defined(__clang__)
#define KAPPA_UNROLL _Pragma("unroll")
#elif defined(__GNUC__)
#define KAPPA_UNROLL _Pragma("GCC unroll 16")
#else
#define KAPPA_UNROLL
#endif

namespace kappa {

namespace {

constexpr int kMaxDegree = 5;
constexpr int kMaxCoefficients = (kMaxDegree + 1) * (kMaxDegree + 2) / 2;
// Equilibrated pivots below this (normal_equations.h) reject a degree.
constexpr double kPivotTolerance = 1e-11;
// cos(5 degrees): jet normals further than this from the fitting frame's
// axis are fitted again in their own frame.
constexpr float kRefitCosine = 0.9962f;
// cos(60 degrees): ring vertices whose normal is further than this from the
// vertex's are left out (beyond, the height function's slope exceeds 1.7).
constexpr float kSideCosine = 0.5f;
// Half a float ulp relative to a coordinate: the largest rounding of a
// position. Rounding alone leaves an RMS fit residual of about 0.3 to 0.4
// times that (uniform rounding error, ulp / sqrt(12), less the fitted
// degrees of freedom); below kRoundingResidual times it, the fit is
// rounding-limited.
constexpr double kFloatRounding = 6e-8;
constexpr double kRoundingResidual = 0.3;

// Unknowns of a degree-d jet: 6, 10, 15, 21 for d = 2, 3, 4, 5.
int coefficient_count(int degree) { return (degree + 1) * (degree + 2) / 2; }

// Points needed to fit a degree: a few more than the unknowns, so a noisy
// fit is still overdetermined.
size_t points_needed(int degree) { return size_t(coefficient_count(degree)) + 3; }

// Monomials x^kPowerX y^kPowerY: 1, x, y, x^2, xy, y^2, x^3, x^2 y, x y^2,
// y^3, x^4, ..., y^4, x^5, ..., y^5: ordered by degree, so the leading block of the normal
// equations is the lower-degree fit.
constexpr int kPowerX[kMaxCoefficients] = {0, 1, 0, 2, 1, 0, 3, 2, 1, 0, 4, 3, 2, 1, 0, 5, 4, 3, 2, 1, 0};
constexpr int kPowerY[kMaxCoefficients] = {0, 0, 1, 0, 1, 2, 0, 1, 2, 3, 0, 1, 2, 3, 4, 0, 1, 2, 3, 4, 5};

struct VertexJet {
    glm::vec3 normal;
    Tensor2 tensor;
    glm::vec4 dcurv{0.0f};
    bool full = false;  // degree 4 (or the degree asked for, if lower) on a sufficient neighbourhood
    double residual = 0;  // RMS height residual of the fit, model units
};

// Fits the jet of vertex v over `ring` (v first) in the frame (u, w, n) and
// reads normal, II and C off it. Returns false when no degree >= 2 fits.
// Top: the largest degree the normal equations are built for (a constant,
// so the moment loops unroll); `degree` <= Top is tried first.
template <int Top>
bool fit_vertex(const Mesh& mesh, const std::vector<uint32_t>& ring, const glm::dvec3& n, int degree,
                VertexJet& out) {
    constexpr int kUnknowns = (Top + 1) * (Top + 2) / 2;
    const glm::dvec3 p0(mesh.positions[ring[0]]);
    glm::vec3 fu, fw;
    tangent_frame(glm::vec3(n), fu, fw);
    const glm::dvec3 u(fu), w(fw);
    double scale = 0;
    for (uint32_t q : ring) {
        const glm::dvec3 d = glm::dvec3(mesh.positions[q]) - p0;
        scale = std::max(scale, glm::dot(d, d));
    }
    if (!(scale > 0) || !std::isfinite(scale)) return false;
    scale = std::sqrt(scale);
    const double inv = 1.0 / scale;
    // A^T A of the monomial rows holds only the moments sum x^i y^j,
    // i + j <= 2 degree (45 for degree 4), and A^T z the sums z x^i y^j,
    // i + j <= degree: accumulating those costs a third of the row-by-row
    // products.
    double moment[2 * Top + 1][2 * Top + 1] = {}, zmoment[Top + 1][Top + 1] = {}, zz = 0;
    for (uint32_t q : ring) {
        const glm::dvec3 d = (glm::dvec3(mesh.positions[q]) - p0) * inv;
        const double x = glm::dot(d, u), y = glm::dot(d, w), z = glm::dot(d, n);
        double px[2 * Top + 1], py[2 * Top + 1];
        px[0] = py[0] = 1;
        KAPPA_UNROLL
        for (int i = 1; i <= 2 * Top; ++i) {
            px[i] = px[i - 1] * x;
            py[i] = py[i - 1] * y;
        }
        KAPPA_UNROLL
        for (int i = 0; i <= 2 * Top; ++i) {
            KAPPA_UNROLL
            for (int j = 0; j + i <= 2 * Top; ++j) moment[i][j] += px[i] * py[j];
        }
        KAPPA_UNROLL
        for (int i = 0; i <= Top; ++i) {
            KAPPA_UNROLL
            for (int j = 0; j + i <= Top; ++j) zmoment[i][j] += z * px[i] * py[j];
        }
        zz += z * z;
    }
    NormalEquations<kUnknowns> eq;
    eq.set_btb(zz);
    for (int a = 0; a < kUnknowns; ++a) {
        eq.set_rhs(a, zmoment[kPowerX[a]][kPowerY[a]]);
        for (int b = a; b < kUnknowns; ++b) eq.set(a, b, moment[kPowerX[a] + kPowerX[b]][kPowerY[a] + kPowerY[b]]);
    }
    double c[kUnknowns];
    int used = 0;
    for (int deg = degree; deg >= 2; --deg) {
        if (ring.size() < points_needed(deg)) continue;
        if (eq.solve(coefficient_count(deg), c, kPivotTolerance)) {
            used = deg;
            break;
        }
    }
    if (used == 0) return false;
    const int k = coefficient_count(used);
    out.residual = ring.size() > size_t(k) ? std::sqrt(eq.residual(c, k) / double(ring.size() - k)) * scale : 0.0;
    // Derivatives at the origin in model units: f(x) = scale f'(x / scale).
    HeightDerivatives h;
    h.fx = c[1];
    h.fy = c[2];
    h.fxx = 2 * c[3] * inv;
    h.fxy = c[4] * inv;
    h.fyy = 2 * c[5] * inv;
    const double inv2 = inv * inv;
    h.fxxx = 6 * c[6] * inv2;
    h.fxxy = 2 * c[7] * inv2;
    h.fxyy = 2 * c[8] * inv2;
    h.fyyy = 6 * c[9] * inv2;
    const glm::dvec3 nl = graph_normal(h);  // in (u, w, n)
    const glm::dvec3 normal = glm::normalize(nl.x * u + nl.y * w + nl.z * n);
    out.normal = glm::vec3(normal);
    glm::vec3 e1, e2;
    tangent_frame(out.normal, e1, e2);
    auto local = [&](const glm::vec3& e) {
        const glm::dvec3 d(e);
        return glm::dvec3(glm::dot(d, u), glm::dot(d, w), glm::dot(d, n));
    };
    double II[3], C[4];
    graph_curvature(h, local(e1), local(e2), II, C);
    for (double x : II)
        if (!std::isfinite(x)) return false;
    for (double x : C)
        if (!std::isfinite(x)) return false;
    out.tensor = {float(II[0]), float(II[1]), float(II[2])};
    out.dcurv = glm::vec4(float(C[0]), float(C[1]), float(C[2]), float(C[3]));
    out.full = used >= std::min(degree, 4);
    return true;
}

bool fit_vertex(const Mesh& mesh, const std::vector<uint32_t>& ring, const glm::dvec3& n, int degree,
                VertexJet& out) {
    return degree > 4 ? fit_vertex<5>(mesh, ring, n, degree, out) : fit_vertex<4>(mesh, ring, n, degree, out);
}

}  // namespace

JetPlan jet_plan_for_noise(float relative_noise) {
    if (!(relative_noise >= 3e-4f)) return {5, 3};
    if (relative_noise < 2e-3f) return {4, 3};
    if (relative_noise < 1e-2f) return {4, 4};
    return {4, 5};
}

CurvatureEstimate estimate_jet(const EstimatorInput& in, const JetOptions& options) {
    const size_t nv = in.mesh.vertex_count();
    JetPlan plan{options.degree, options.rings};
    if (plan.degree <= 0 || plan.rings <= 0) {
        const JetPlan automatic = jet_plan_for_noise(estimate_noise_level(in.mesh, in.vf, in.normals).relative);
        if (plan.degree <= 0) plan.degree = automatic.degree;
        if (plan.rings <= 0) plan.rings = automatic.rings;
    }
    const int degree = std::clamp(plan.degree, 2, kMaxDegree);
    const int base_rings = plan.rings;
    const int max_rings = std::max(base_rings, options.max_rings);
    const VertexAdjacency adj = build_vertex_adjacency(in.mesh, in.vf);
    CurvatureEstimate out = empty_estimate(nv, true);
    out.normals = in.normals;
    const bool grow_when_exact = options.rings <= 0;
    parallel_for_ranges(nv, [&](size_t begin, size_t end) {
        RingCollector rings(nv);
        std::vector<uint32_t> ring;
        // Fits vertex v over `all` less the vertices facing away by more than
        // 60 degrees (the surface is a usable height function over the
        // tangent plane only there: a ring that wraps round a thin part, an
        // ear, reaches the other side);
        // again in the jet normal's frame where the vertex normal was more
        // than 5 degrees off (a poor normal, e.g. at folded triangles).
        const auto fit_ring = [&](const std::vector<uint32_t>& all, size_t v, VertexJet& jet) {
            ring.clear();
            for (uint32_t q : all)
                if (q == v || glm::dot(in.normals[q], in.normals[v]) > kSideCosine) ring.push_back(q);
            if (!fit_vertex(in.mesh, ring, glm::dvec3(in.normals[v]), degree, jet)) return false;
            for (int again = 0; options.refit && again < 2 && glm::dot(jet.normal, in.normals[v]) < kRefitCosine;
                 ++again) {
                VertexJet refit;
                if (!fit_vertex(in.mesh, ring, glm::dvec3(jet.normal), degree, refit)) break;
                const bool settled = glm::dot(refit.normal, jet.normal) >= kRefitCosine;
                jet = refit;
                if (settled) break;
            }
            return true;
        };
        for (size_t v = begin; v < end; ++v) {
            const std::vector<uint32_t>& all = rings.collect(adj, uint32_t(v), base_rings);
            for (int r = base_rings; all.size() < points_needed(degree) && r < max_rings;) {
                const size_t before = all.size();
                r = rings.grow(adj);
                if (all.size() == before) break;
            }
            VertexJet jet;
            if (!fit_ring(all, v, jet)) {
                out.flags[v] = kFlagFallback;
                continue;
            }
            // A residual at the level of the positions' float rounding means
            // truncation is negligible and rounding dominates: a wider ring
            // averages it down (flat regions, fine tessellations).
            const glm::vec3 p0 = in.mesh.positions[v];
            const double rounding =
                kFloatRounding * std::max({std::fabs(p0.x), std::fabs(p0.y), std::fabs(p0.z)});
            if (grow_when_exact && jet.residual < kRoundingResidual * rounding) {
                const size_t before = all.size();
                rings.grow(adj);
                VertexJet wider;
                // Kept only if it is rounding-limited too: a wider ring that
                // reaches other features (or damage) is not a better fit.
                if (all.size() > before && fit_ring(all, v, wider) &&
                    wider.residual < 2 * kRoundingResidual * rounding)
                    jet = wider;
            }
            out.normals[v] = jet.normal;
            out.tensors.tensor[v] = jet.tensor;
            out.dcurv_uv[v] = jet.dcurv;
            if (!jet.full) out.flags[v] = kFlagFallback;
        }
    });
    return out;
}

}  // namespace kappa
