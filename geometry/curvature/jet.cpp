#include "jet.h"

#include "graph_geometry.h"
#include "normal_equations.h"
#include "rings.h"

#include "geometry/parallel/double_lanes.h"
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
// The RMS of a height's rounding error relative to kFloatRounding times the
// largest coordinate (uniform error: 1 / sqrt(3) of its bound, the bound
// 0.5 to 1 times kFloatRounding |x|).
constexpr double kRoundingNoise = 0.45;
// The inner candidate's ring. choose_terms' thresholds: for the curvature
// terms 2, about 2 / (1 + beta) with beta = (2/3)^4 (truncation of jets of
// degree 4 and 5 goes as the fourth power of the ring's radius); for C, 9:
// a C from the 2-ring is far noisier (measured on spheres, tori,
// ellipsoids and cubic patches of 162 to 80k vertices, as the accuracy lab
// builds them: 9 keeps the 3-ring's C on fine meshes, where rounding rules,
// and takes the 2-ring's on coarse ones). kQuinticF: the F value (6 and
// about 16 degrees of freedom) above which the fifth-order terms count,
// about its 99th percentile.
constexpr int kInnerRings = 2;
constexpr double kCurvatureAgreement = 2.0, kDcurvAgreement = 9.0;
constexpr double kQuinticF = 4.0;
// The mesh's noise for choose_terms: from at most this many vertices
// (JetFitter::noise2).
constexpr size_t kNoiseSamples = 4096;
// Relative noise below which a mesh counts as clean (jet_plan_for_noise).
constexpr float kCleanNoise = 3e-4f;
// The first look at the noise (JetFitter::noise2): every kFirstLook-th
// sample; it settles a plan estimate above kFirstLookMargin times the clean
// threshold, from at least kFirstLookSamples fits (their median's sampling
// error is a few percent). Measured plan estimates over the threshold:
// clean lab meshes and fandisk below 0.33, noisy scans (spot, bunny,
// dragon) 22 to 150.
constexpr size_t kFirstLook = 8, kFirstLookSamples = 256;
constexpr float kFirstLookMargin = 8;

// The largest rounding of a position's coordinates: kFloatRounding times the largest.
double vertex_rounding(const glm::vec3& p) {
    return kFloatRounding * std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
}

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
};

// The terms a choice compares: the curvature's (x^2, xy, y^2) and C's
// (x^3, ..., y^3), as indices of the coefficients.
constexpr int kCurvatureTerms[3] = {3, 4, 5};
constexpr int kDcurvTerms[4] = {6, 7, 8, 9};

// One candidate fit of a vertex: its coefficients up to degree 3 (scaled
// coordinates x / scale, frame (u, w, n)) and the variance factors of its
// curvature terms and of its C terms (each summed, for unit height noise).
struct JetCandidate {
    double c[10];
    double variance[2];
};

// One vertex's candidate fits, from the least noisy to the least biased
// (choose_terms): with a degree-5 fit, degree 4 over the same ring, the
// degree-5 fit, and the inner fit (degree 4 on the 2-ring, the degree-5
// fit's fifth-order part subtracted from the heights first); with a
// degree-4 fit, it and the inner fit (plain).
struct JetFit {
    JetCandidate candidate[3];
    int count = 0, planned = 0;  // candidates; the index of the plan's own fit
    int outer = 0;               // the whole ring's candidate choose_terms weighs against the inner one
    bool has_inner = false;      // the last candidate is the inner fit
    glm::dvec3 u, w, n;
    double scale = 1;
    bool full = false;         // the plan's fit: degree 4 (or the degree asked for) or more
    double residual = 0;       // RMS height residual of the plan's fit, model units
    // Median-unbiased sigma^2 estimates (model units; < 0: none) of plain
    // degree-4 fits on the inner points and on the whole ring (JetFitter::noise2).
    double inner_noise2 = -1, outer_noise2 = -1;
    // The same of the inner candidate and of the plan's fit (choose_terms' noise).
    double nested_noise2 = -1, planned_noise2 = -1;

    // The plan's fit's normal (only its gradient).
    glm::vec3 planned_normal() const {
        const double* c = candidate[planned].c;
        return glm::vec3(glm::normalize(-c[1] * u - c[2] * w + n));
    }
};

// Reads the normal, II and C off the coefficients c (scaled coordinates,
// frame (u, w, n)), gradient included. False on non-finite values.
bool read_jet(const double (&c)[10], double inv, const glm::dvec3& u, const glm::dvec3& w, const glm::dvec3& n,
              VertexJet& out) {
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
    return true;
}

// The median of the values >= 0 (0 when none); reorders them.
double median_of_valid(std::vector<double>& values) {
    values.erase(std::remove_if(values.begin(), values.end(), [](double x) { return !(x >= 0); }), values.end());
    if (values.empty()) return 0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

// The Wilson-Hilferty median of chi^2(k) / k: divides a residual variance
// with k degrees of freedom to make it median-unbiased (noise_level.h).
double chi2_median_factor(double k) { return std::pow(1.0 - 2.0 / (9.0 * k), 3.0); }

// The sums a jet's normal equations are made of, up to degree Top: A^T A of
// the monomial rows holds only the moments sum x^i y^j, i + j <= 2 Top (66
// for degree 5), and A^T z the sums z x^i y^j, i + j <= Top: accumulating
// those costs a third of the row-by-row products. Kept in pairs along j
// (one SSE2 register: two sums an operation, each summed as it would be alone).
template <int Top>
struct RingMoments {
    static constexpr int kPowers = 2 * Top + 1;  // x^0 .. x^(2 Top)
    static constexpr int kPairs = (kPowers + 1) / 2;
    static constexpr int kZPairs = (Top + 2) / 2;
    static constexpr int kRow = 2 * kPairs, kZRow = 2 * kZPairs;
    alignas(16) double xy[kPowers * kRow] = {};  // xy[i kRow + j]: sum x^i y^j
    alignas(16) double z[(Top + 1) * kZRow] = {};  // z[i kZRow + j]: sum h x^i y^j
    double zz = 0;

    // One point (x, y) with height h.
    void add(double x, double y, double h) {
        double px[kPowers], py[2 * kPairs];
        px[0] = py[0] = 1;
        KAPPA_UNROLL
        for (int i = 1; i < kPowers; ++i) px[i] = px[i - 1] * x;
        KAPPA_UNROLL
        for (int i = 1; i < 2 * kPairs; ++i) py[i] = py[i - 1] * y;
        lanes::Doubles2 pairs[kPairs];
        KAPPA_UNROLL
        for (int p = 0; p < kPairs; ++p) pairs[p] = lanes::load_pair(&py[2 * p]);
        KAPPA_UNROLL
        for (int i = 0; i < kPowers; ++i) {
            const lanes::Doubles2 a{px[i], px[i]};
            KAPPA_UNROLL
            for (int p = 0; 2 * p + i < kPowers; ++p)
                lanes::store_pair(&xy[i * kRow + 2 * p], lanes::load_pair(&xy[i * kRow + 2 * p]) + a * pairs[p]);
        }
        KAPPA_UNROLL
        for (int i = 0; i <= Top; ++i) {
            const double hx = h * px[i];
            const lanes::Doubles2 a{hx, hx};
            KAPPA_UNROLL
            for (int p = 0; 2 * p + i <= Top; ++p)
                lanes::store_pair(&z[i * kZRow + 2 * p], lanes::load_pair(&z[i * kZRow + 2 * p]) + a * pairs[p]);
        }
        zz += h * h;
    }

    // Entry (a, b) of A^T A and entry a of A^T z (monomials numbered as kPowerX, kPowerY).
    double ata(int a, int b) const { return xy[kOffsets.ata[a][b]]; }
    double atz(int a) const { return z[kOffsets.atz[a]]; }

private:
    // Where those sums are in xy and z (for Top < 5, only those of its unknowns).
    struct Offsets {
        int ata[kMaxCoefficients][kMaxCoefficients], atz[kMaxCoefficients];
    };
    static constexpr Offsets offsets() {
        Offsets o{};
        for (int a = 0; a < kMaxCoefficients; ++a) {
            for (int b = 0; b < kMaxCoefficients; ++b)
                o.ata[a][b] = (kPowerX[a] + kPowerX[b]) * kRow + kPowerY[a] + kPowerY[b];
            o.atz[a] = kPowerX[a] * kZRow + kPowerY[a];
        }
        return o;
    }
    static constexpr Offsets kOffsets = offsets();
};

// Fits the jet of vertex v over `ring` (v first) in the frame (u, w, n) and,
// with inner >= points_needed(4), the inner candidate over ring[0, inner)
// (the 2-ring: rings are breadth-first). Returns false when no degree >= 2
// fits the whole ring. Top: the largest degree the normal equations are
// built for (a constant, so the moment loops unroll); `degree` <= Top is
// tried first.
template <int Top>
bool fit_vertex(const Mesh& mesh, const std::vector<uint32_t>& ring, const glm::dvec3& n, int degree, size_t inner,
                bool noise_fits, JetFit& out) {
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
    // The inner candidate's sums are those over the first `inner` points.
    RingMoments<Top> sums, inner_sums;
    const bool with_inner = inner >= points_needed(4) && inner < ring.size();
    // Points [begin, end) into the sums (one loop without branches: it unrolls).
    const auto accumulate = [&](size_t begin, size_t end) {
        for (size_t index = begin; index < end; ++index) {
            const glm::dvec3 d = (glm::dvec3(mesh.positions[ring[index]]) - p0) * inv;
            sums.add(glm::dot(d, u), glm::dot(d, w), glm::dot(d, n));
        }
    };
    const size_t split = with_inner ? inner : ring.size();
    accumulate(0, split);
    if (with_inner) inner_sums = sums;
    accumulate(split, ring.size());
    // One factorisation for every degree: a lower degree's fit is its
    // leading block (normal_equations.h).
    NestedFits<kUnknowns> fits([&](int a, int b) { return sums.ata(a, b); }, coefficient_count(degree),
                               kPivotTolerance);
    double atz[kUnknowns];
    for (int a = 0; a < kUnknowns; ++a) atz[a] = sums.atz(a);
    fits.set_rhs(atz, sums.zz);
    double c[kUnknowns];
    int used = 0;
    for (int deg = degree; deg >= 2; --deg) {
        if (ring.size() < points_needed(deg)) continue;
        if (coefficient_count(deg) <= fits.rank() && fits.solve(coefficient_count(deg), c)) {
            used = deg;
            break;
        }
    }
    if (used == 0) return false;
    const int k = coefficient_count(used);
    const double rss = fits.residual(k);
    out.u = u;
    out.w = w;
    out.n = n;
    out.scale = scale;
    out.full = used >= std::min(degree, 4);
    out.residual = ring.size() > size_t(k) ? std::sqrt(rss / double(ring.size() - k)) * scale : 0.0;
    out.inner_noise2 = out.outer_noise2 = out.nested_noise2 = out.planned_noise2 = -1;
    if (ring.size() >= size_t(k) + 2) {
        const double dof = double(ring.size()) - k;
        out.planned_noise2 = rss / dof / chi2_median_factor(dof) * scale * scale;
    }
    out.count = 0;
    out.outer = 0;
    out.has_inner = false;
    double c4[kUnknowns];
    const bool with_quartic = with_inner && used == 5 && fits.solve(15, c4);
    if (with_quartic) {
        const double rss4 = fits.residual(15), dof4 = double(ring.size()) - 15;
        if (dof4 >= 2) out.outer_noise2 = rss4 / dof4 / chi2_median_factor(dof4) * scale * scale;
        // The F test of the fifth-order terms (6 of them) against the
        // degree-5 fit's residual: where they explain no more than it,
        // degree 4 on the same ring (less noisy) is the outer fit.
        const double dof = double(ring.size()) - k;
        const double f = dof >= 1 && rss > 0 ? (rss4 - rss) / 6 / (rss / dof) : 1e300;
        if (!(f < kQuinticF)) out.outer = 1;
    }
    // Variance factors of the curvature and C terms, only where the choice
    // will weigh them: in the outer fit (choose_terms).
    constexpr int kTerms[7] = {3, 4, 5, 6, 7, 8, 9};  // kCurvatureTerms, then kDcurvTerms
    const int terms = !with_inner ? 0 : used >= 3 ? 7 : 3;
    const int outer_model = with_quartic && out.outer == 0 ? 15 : k;
    double variance[7][kUnknowns + 1];
    if (terms == 7) fits.variances(kTerms, outer_model, variance);
    if (terms == 3) fits.variances(kCurvatureTerms, outer_model, variance);
    // Stores a solution as the next candidate, with model m's variance
    // factors (of the first `count` terms) summed per group (0 where not computed).
    const auto keep = [&](const double* x, const auto& factors, int count, int m, int computed) {
        JetCandidate& cand = out.candidate[out.count++];
        std::copy(x, x + 10, cand.c);
        cand.variance[0] = cand.variance[1] = 0.0;
        if (m <= computed)
            for (int t = 0; t < count; ++t) cand.variance[t < 3 ? 0 : 1] += factors[t][m];
    };
    if (with_quartic) keep(c4, variance, terms, 15, outer_model);
    out.planned = out.count;
    keep(c, variance, terms, k, outer_model);
    if constexpr (Top == 5) {
        if (!with_inner || used < 4) return true;
        // The inner candidate: degree 4 on the inner points, heights less
        // the plan's fit's terms of degree 5 (none for a degree-4 fit):
        // A^T (z - A5 c5) and |z - A5 c5|^2 from the same moments.
        constexpr int k4 = 15;
        NestedFits<k4> inner_fits([&](int a, int b) { return inner_sums.ata(a, b); }, k4, kPivotTolerance);
        if (inner_fits.rank() < k4) return true;
        double zz5 = inner_sums.zz;
        for (int m = k4; m < k; ++m) {
            zz5 -= 2 * c[m] * inner_sums.atz(m);
            for (int m2 = k4; m2 < k; ++m2) zz5 += c[m] * c[m2] * inner_sums.ata(m, m2);
        }
        double plain[k4], nested[k4];
        for (int a = 0; a < k4; ++a) {
            plain[a] = nested[a] = inner_sums.atz(a);
            for (int m = k4; m < k; ++m) nested[a] -= c[m] * inner_sums.ata(a, m);
        }
        inner_fits.set_rhs(nested, zz5);
        double ci[k4];
        if (!inner_fits.solve(k4, ci)) return true;
        double inner_variance[7][k4 + 1];
        inner_fits.variances(kTerms, k4, inner_variance);
        keep(ci, inner_variance, 7, k4, k4);
        out.has_inner = true;
        const double dof = double(inner) - k4;
        if (dof >= 2) out.nested_noise2 = inner_fits.residual(k4) / dof / chi2_median_factor(dof) * scale * scale;
        if (noise_fits && dof >= 2) {  // a plain degree-4 fit on the inner points: the same A^T A
            inner_fits.set_rhs(plain, inner_sums.zz);
            const double rss_plain = inner_fits.residual(k4);
            if (std::isfinite(rss_plain))
                out.inner_noise2 = rss_plain / dof / chi2_median_factor(dof) * scale * scale;
        }
    }
    return true;
}

bool fit_vertex(const Mesh& mesh, const std::vector<uint32_t>& ring, const glm::dvec3& n, int degree, size_t inner,
                bool noise_fits, JetFit& out) {
    return degree > 4 ? fit_vertex<5>(mesh, ring, n, degree, inner, noise_fits, out)
                      : fit_vertex<4>(mesh, ring, n, degree, inner, noise_fits, out);
}

// Which candidate gives a group of terms (0: curvature, 1: C), for noise
// sigma^2 (model units): the plug-in choice between the outer and the inner
// fit (Lepski's principle with the bias made explicit). The inner fit has
// less bias (a fraction beta of the outer's) and more variance; the outer
// bias b shows in their difference, E|D|^2 = (1 - beta)^2 b^2 + sigma^2 gap
// (gap: the variance of the difference of nested least-squares fits, V_inner
// - V_outer), and the inner fit has the smaller expected error, beta^2 b^2
// + sigma^2 V_inner < b^2 + sigma^2 V_outer, when |D|^2 > 2 / (1 + beta)
// sigma^2 gap. |D|^2 is itself noisy, and where noise dominates (fine
// meshes: rounding) a wrong inner choice costs more than a wrong outer one:
// the thresholds (kCurvatureAgreement, kDcurvAgreement) are at least that.
int choose_terms(const JetFit& fit, int group, double noise2) {
    if (!fit.has_inner) return fit.outer;
    const int inner = fit.count - 1;
    const JetCandidate& a = fit.candidate[fit.outer];
    const JetCandidate& b = fit.candidate[inner];
    const int* terms = group == 0 ? kCurvatureTerms : kDcurvTerms;
    double d2 = 0;
    for (int t = 0; t < (group == 0 ? 3 : 4); ++t) d2 += (a.c[terms[t]] - b.c[terms[t]]) * (a.c[terms[t]] - b.c[terms[t]]);
    const double unit2 = noise2 / (fit.scale * fit.scale);  // heights are scaled by 1 / scale
    const double gap = std::max(b.variance[group] - a.variance[group], 0.0);
    return d2 > (group == 0 ? kCurvatureAgreement : kDcurvAgreement) * unit2 * gap ? inner : fit.outer;
}

// The vertex's normal, II and C: the terms up to degree 2 (normal and II)
// and those of degree 3 (C), each from the candidate choose_terms takes.
bool choose_jet(const JetFit& fit, double noise2, VertexJet& out) {
    double c[10];
    const JetCandidate& curvature = fit.candidate[choose_terms(fit, 0, noise2)];
    const JetCandidate& dcurv = fit.candidate[choose_terms(fit, 1, noise2)];
    std::copy(curvature.c, curvature.c + 6, c);
    std::copy(dcurv.c + 6, dcurv.c + 10, c + 6);
    out.full = fit.full;
    return read_jet(c, 1.0 / fit.scale, fit.u, fit.w, fit.n, out);
}

// Fits every vertex with one degree and ring (JetOptions, or a jet plan).
class JetFitter {
public:
    JetFitter(const EstimatorInput& in, const VertexAdjacency& adj, const JetOptions& options, int degree,
              int rings)
        : in_(in), adj_(adj), options_(options), degree_(std::clamp(degree, 2, kMaxDegree)), rings_(rings),
          max_rings_(std::max(rings, options.max_rings)), automatic_(options.rings <= 0),
          with_inner_(automatic_ && degree_ == 5 && rings > kInnerRings) {}

    // Both fits of vertex v: the ring (grown where too small for the
    // degree), and one ring more where the fit is rounding-limited.
    bool fit(size_t v, RingCollector& rings, std::vector<uint32_t>& ring, JetFit& fit) const {
        const std::vector<uint32_t>& all = rings.collect(adj_, uint32_t(v), std::min(rings_, kInnerRings));
        const size_t inner_all = with_inner_ ? all.size() : 0;
        for (int r = std::min(rings_, kInnerRings); r < rings_;) {
            const size_t before = all.size();
            r = rings.grow(adj_);
            if (all.size() == before) break;
        }
        for (int r = rings_; all.size() < points_needed(degree_) && r < max_rings_;) {
            const size_t before = all.size();
            r = rings.grow(adj_);
            if (all.size() == before) break;
        }
        if (!fit_ring(all, inner_all, v, ring, fit)) return false;
        // A residual at the level of the positions' float rounding means
        // truncation is negligible and rounding dominates: a wider ring
        // averages it down (flat regions, fine tessellations).
        const double rounding = vertex_rounding(in_.mesh.positions[v]);
        if (automatic_ && fit.residual < kRoundingResidual * rounding) {
            const size_t before = all.size();
            rings.grow(adj_);
            JetFit wider;
            // Kept only if it is rounding-limited too: a wider ring that
            // reaches other features (or damage) is not a better fit.
            if (all.size() > before && fit_ring(all, inner_all, v, ring, wider) &&
                wider.residual < 2 * kRoundingResidual * rounding)
                fit = wider;
        }
        return true;
    }

    // Noise variances of the heights from a sample of vertices (every
    // (V / kNoiseSamples)-th), each from the medians of two fits' residual
    // variances R_in^2 = sigma^2 + beta^2 T^2 (2-ring) and R^2 = sigma^2 + T^2
    // (whole ring), T the truncation left on the whole ring and beta its
    // share on the 2-ring, solved for sigma^2. `plan`: plain degree-4 fits,
    // beta = (2/3)^5 (fifth-order terms); unbiased under noise, it decides
    // the plan (unlike the cubic fits of noise_level.h it sees little of a
    // coarse clean mesh's truncation). `choice`: the inner candidates and the
    // degree-5 fits, beta = (2/3)^6; it sees even less truncation but is
    // biased low under noise (the inner fit shares the outer's fifth-order
    // terms), so it serves only the clean plan's choose_terms.
    // The sampled vertices' fits are kept (`fits[i]` of vertex i * step,
    // where `fitted[i]`): where the plan is this fitter's, they are the fits.
    //
    // `noisy` (> 0): a plan estimate far above the clean threshold. A first
    // look at every kFirstLook-th sample that already reads above it (from
    // at least kFirstLookSamples fits) ends the estimate there, with only
    // `plan` (then `noisy_early`): a noisy mesh fits degree 4, without the
    // choice or these fits.
    struct NoiseEstimates {
        double plan = 0, choice = 0;
        bool noisy_early = false;
        size_t step = 0;
        std::vector<JetFit> fits;
        std::vector<uint8_t> fitted;
    };
    NoiseEstimates noise2(double noisy) const {
        const size_t nv = in_.mesh.vertex_count();
        if (!with_inner_ || nv == 0) return {};
        NoiseEstimates out;
        const size_t step = out.step = (nv + kNoiseSamples - 1) / kNoiseSamples;
        const size_t count = (nv + step - 1) / step;
        out.fits.resize(count);
        out.fitted.assign(count, 0);
        // The samples of the first look, or the others.
        const auto fit_samples = [&](bool first_look) {
            noise_fits_ = true;
            parallel_for_ranges(count, [&](size_t begin, size_t end) {
                RingCollector rings(nv);
                std::vector<uint32_t> ring;
                for (size_t i = begin; i < end; ++i)
                    if ((i % kFirstLook == 0) == first_look) out.fitted[i] = fit(i * step, rings, ring, out.fits[i]);
            });
            noise_fits_ = false;
        };
        const auto solve = [](double r_in2, double r2, double beta) {
            const double t2 = std::max(r2 - r_in2, 0.0) / (1 - beta * beta);
            return std::max(r_in2 - beta * beta * t2, 0.0);
        };
        // The fits' residual variances (-1 where none), of the first look's samples only or of all.
        const auto residuals = [&](bool first_look, double JetFit::*quantity) {
            std::vector<double> values;
            for (size_t i = 0; i < count; ++i)
                if (!first_look || i % kFirstLook == 0) values.push_back(out.fitted[i] ? out.fits[i].*quantity : -1.0);
            return values;
        };
        fit_samples(true);
        if (noisy > 0) {
            std::vector<double> inner = residuals(true, &JetFit::inner_noise2);
            std::vector<double> outer = residuals(true, &JetFit::outer_noise2);
            const size_t valid = size_t(std::count_if(inner.begin(), inner.end(), [](double x) { return x >= 0; }));
            const double plan = solve(median_of_valid(inner), median_of_valid(outer), 32.0 / 243.0);
            if (valid >= kFirstLookSamples && plan > noisy) {
                out.plan = plan;
                out.noisy_early = true;
                return out;
            }
        }
        fit_samples(false);
        std::vector<double> inner = residuals(false, &JetFit::inner_noise2);
        std::vector<double> outer = residuals(false, &JetFit::outer_noise2);
        std::vector<double> nested = residuals(false, &JetFit::nested_noise2);
        std::vector<double> planned = residuals(false, &JetFit::planned_noise2);
        out.plan = solve(median_of_valid(inner), median_of_valid(outer), 32.0 / 243.0);
        out.choice = solve(median_of_valid(nested), median_of_valid(planned), 64.0 / 729.0);
        return out;
    }

private:
    // Fits vertex v over `all` less the vertices facing away by more than
    // 60 degrees (the surface is a usable height function over the tangent
    // plane only there: a ring that wraps round a thin part, an ear, reaches
    // the other side); again in the jet normal's frame where the vertex
    // normal was more than 5 degrees off (a poor normal, e.g. at folded
    // triangles). `inner_all`: the 2-ring's size in `all` (0: no inner fit).
    bool fit_ring(const std::vector<uint32_t>& all, size_t inner_all, size_t v, std::vector<uint32_t>& ring,
                  JetFit& fit) const {
        ring.clear();
        size_t inner = 0;
        for (size_t i = 0; i < all.size(); ++i) {
            const uint32_t q = all[i];
            if (q == v || glm::dot(in_.normals[q], in_.normals[v]) > kSideCosine) ring.push_back(q);
            if (i + 1 == inner_all) inner = ring.size();
        }
        if (!fit_vertex(in_.mesh, ring, glm::dvec3(in_.normals[v]), degree_, inner, noise_fits_, fit)) return false;
        for (int again = 0; options_.refit && again < 2 && glm::dot(fit.planned_normal(), in_.normals[v]) < kRefitCosine;
             ++again) {
            JetFit refit;
            if (!fit_vertex(in_.mesh, ring, glm::dvec3(fit.planned_normal()), degree_, inner, noise_fits_, refit)) break;
            const bool settled = glm::dot(refit.planned_normal(), fit.planned_normal()) >= kRefitCosine;
            fit = refit;
            if (settled) break;
        }
        return true;
    }

    const EstimatorInput& in_;
    const VertexAdjacency& adj_;
    const JetOptions& options_;
    int degree_, rings_, max_rings_;
    bool automatic_, with_inner_;
    mutable bool noise_fits_ = false;  // during noise2() only
};

}  // namespace

JetPlan jet_plan_for_noise(float relative_noise) {
    if (!(relative_noise >= kCleanNoise)) return {5, 3};
    if (relative_noise < 2e-3f) return {4, 3};
    if (relative_noise < 1e-2f) return {4, 4};
    return {4, 5};
}

CurvatureEstimate estimate_jet(const EstimatorInput& in, const JetOptions& options) {
    const size_t nv = in.mesh.vertex_count();
    const VertexAdjacency adj = build_vertex_adjacency(in.mesh, in.vf);
    JetPlan plan{options.degree, options.rings};
    double noise2 = 0;  // the heights' noise variance for the inner choice
    const JetPlan clean = jet_plan_for_noise(0);
    JetFitter::NoiseEstimates estimates;
    if (plan.degree <= 0 || plan.rings <= 0) {
        // The noise level (scale/noise_level.h) reads a cubic fit's
        // truncation as noise on coarse clean meshes; the clean plan's
        // degree-4 fits on two rings see far less of it (JetFitter::noise2).
        const float median_edge = sampled_median_edge(in.mesh, in.vf);
        // Where the degree is automatic, a plan estimate kFirstLookMargin
        // times the clean threshold settles it at a first look (noise2).
        const double noisy = options.degree <= 0 ? std::pow(kFirstLookMargin * kCleanNoise * median_edge, 2) : 0.0;
        estimates = JetFitter(in, adj, options, clean.degree, clean.rings).noise2(noisy);
        noise2 = estimates.choice;
        const float relative = median_edge > 0 ? float(std::sqrt(estimates.plan)) / median_edge : 0.0f;
        // Only to tell clean from noisy: on noisy meshes the cubic level
        // (within 3% of the truth) keeps choosing the rings.
        const JetPlan automatic = jet_plan_for_noise(
            relative < kCleanNoise ? relative : estimate_noise_level(in.mesh, in.vf, in.normals).relative);
        if (plan.degree <= 0) plan.degree = automatic.degree;
        if (plan.rings <= 0) plan.rings = automatic.rings;
    }
    const JetFitter fitter(in, adj, options, plan.degree, plan.rings);
    // The noise estimate's fits are this plan's where it is the clean one.
    const size_t sampled =
        plan.degree == clean.degree && plan.rings == clean.rings && !estimates.noisy_early ? estimates.step : 0;
    CurvatureEstimate out = empty_estimate(nv, true);
    out.normals = in.normals;
    parallel_for_ranges(nv, [&](size_t begin, size_t end) {
        RingCollector rings(nv);
        std::vector<uint32_t> ring;
        JetFit fit;
        for (size_t v = begin; v < end; ++v) {
            VertexJet jet;
            const double rounding = kRoundingNoise * vertex_rounding(in.mesh.positions[v]);
            bool fitted;
            if (sampled > 0 && v % sampled == 0) {
                fit = estimates.fits[v / sampled];
                fitted = estimates.fitted[v / sampled] != 0;
            } else {
                fitted = fitter.fit(v, rings, ring, fit);
            }
            if (!fitted || !choose_jet(fit, std::max(noise2, rounding * rounding), jet)) {
                out.flags[v] = kFlagFallback;
                continue;
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
