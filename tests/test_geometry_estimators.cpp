// The estimators of geometry/curvature/ against exact analytic truth
// (analytic_curvature.h): what the mathematics guarantees (jets exact on
// polynomials of their degree, convergence orders, exactness on spheres),
// and the accuracy lab's orderings with bounds measured (2026-11-23, printed
// by INFO) and given margins. The full figures: scripts/accuracy-lab.sh.
#include "analytic_estimate.h"

#include "geometry/curvature/jet.h"
#include "geometry/curvature/normal_fit.h"
#include "geometry/parallel/parallel.h"
#include "geometry/surface_analysis.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>

using namespace kappa;
using test::AnalyticMesh;

namespace {

SurfaceFields fields(const Mesh& m, Estimator e) {
    SmoothingOptions o;
    o.estimator = e;
    return compute_surface_fields(m, o);
}

using Errors = test::RelativeErrors;

Errors errors(const SurfaceFields& f, const AnalyticMesh& a) {
    return {test::relative_curvature_error(f, a), test::relative_dcurv_error(f, a)};
}

Errors errors(const CurvatureEstimate& e, const AnalyticMesh& a) { return test::relative_errors(e, a); }

JetOptions jet_options(int degree, int rings, bool refit = true) {
    JetOptions o;
    o.degree = degree;
    o.rings = rings;
    o.refit = refit;
    return o;
}

}  // namespace

TEST_CASE("The analytic C truth matches the torus formula of conventions.md", "[estimators][truth]") {
    // |C| = sqrt(3) R |sin v| / (r (R + r cos v)^2), independent of the frame.
    const AnalyticMesh a = test::analytic_torus(1, 0.4, 40, 20, 0.3, 5);
    for (size_t i = 0; i < a.dcurv.size(); ++i) {
        const glm::dvec3 p(a.mesh.positions[i]);
        const double v = std::atan2(p.z, std::hypot(p.x, p.y) - 1.0);
        const double expected = std::sqrt(3.0) * std::fabs(std::sin(v)) / (0.4 * std::pow(1 + 0.4 * std::cos(v), 2));
        const glm::dvec4 C = a.dcurv[i];
        CHECK(std::sqrt(C[0] * C[0] + 3 * C[1] * C[1] + 3 * C[2] * C[2] + C[3] * C[3]) ==
              Approx(expected).margin(1e-5));
    }
}

TEST_CASE("Jets of degree 3 to 5 are exact on cubic height functions up to rounding", "[estimators][jet]") {
    // In the cubic's own frame (every normal (0, 0, 1)) the height of any
    // 2-ring is a cubic polynomial, so the fit reproduces it and the
    // read-off (gradient included) is exact. What remains is float rounding
    // of the positions, ~1e-7 over a ring of radius r ~ 2h, amplified by
    // the fit (~3 for curvature, ~10 for C): ~3e-7 / r^2 in curvature and
    // ~1e-6 / r^3 in C, for RMS curvature ~1 and |C| ~3 here (h = 1/12):
    // about 1e-5 and 3e-5 relative. A coarse grid keeps rounding far below
    // what truncation would give (the quadratic jet below).
    const AnalyticMesh a = test::analytic_cubic_patch(24, 0.5, 0.3, 0.7, 4);
    test::EstimatorInputs in = test::estimator_inputs(a.mesh);
    std::fill(in.normals.begin(), in.normals.end(), glm::vec3(0, 0, 1));
    for (int degree : {3, 4, 5}) {
        const bool refit = false;  // stay in the cubic's frame
        const Errors e = errors(estimate_jet(in.of(a.mesh), jet_options(degree, 2, refit)), a);
        INFO("degree " << degree << ": curvature " << e.curvature << ", C " << e.dcurv);
        CHECK(e.curvature < 1e-4);
        CHECK(e.dcurv < 3e-4);
    }
    // A quadratic jet cannot follow the cubic terms: the check can fail.
    const Errors e2 = errors(estimate_jet(in.of(a.mesh), jet_options(2, 2, false)), a);
    INFO("degree 2: curvature " << e2.curvature);
    CHECK(e2.curvature > 1e-2);
}

TEST_CASE("The degree-4 jet converges at order 3 in curvature and 2 in C on a torus", "[estimators][jet]") {
    // Cazals & Pouget 2003, Th. 3: a degree-n jet gives the k-th derivatives
    // with error O(h^(n-k+1)): for n = 4, curvature (k = 2) O(h^3), C (k = 3) O(h^2).
    // Halving h should divide the errors by 8 and 4; measured 10.4 and 3.8.
    const AnalyticMesh coarse = test::analytic_torus(1, 0.4, 100, 50), fine = test::analytic_torus(1, 0.4, 200, 100);
    auto jet = [&](const AnalyticMesh& a) {  // the same neighbourhood and degree at both sizes
        return errors(estimate_jet(test::estimator_inputs(a.mesh).of(a.mesh), jet_options(4, 2)), a);
    };
    const Errors ec = jet(coarse), ef = jet(fine);
    INFO("curvature " << ec.curvature << " -> " << ef.curvature << ", C " << ec.dcurv << " -> " << ef.dcurv);
    CHECK(ec.curvature / ef.curvature > 6.0);
    CHECK(ec.dcurv / ef.dcurv > 3.0);
    // The paper's method on the same regular tessellation: second order.
    const Errors rc = errors(fields(coarse.mesh, Estimator::rusinkiewicz), coarse);
    const Errors rf = errors(fields(fine.mesh, Estimator::rusinkiewicz), fine);
    INFO("rusinkiewicz curvature " << rc.curvature << " -> " << rf.curvature);
    CHECK(rc.curvature / rf.curvature > 3.0);
}

TEST_CASE("The normal-curvature fit is exact on spheres", "[estimators][sphere]") {
    // Eq. 3 is the curvature of the circle through both ends with the exact
    // normal at one, which on a sphere is the great circle: 1/R exactly, and
    // Max's normals are exact there. Float rounding as in the paper's
    // sphere test (test_geometry_curvature.cpp), where its own exactness is asserted.
    for (uint32_t seed = 1; seed <= 2; ++seed) {
        const Mesh m = make_jittered_sphere(1.5f, 4, 0.9f, seed);
        const SurfaceFields s = fields(m, Estimator::normal_fit);
        double worst = 0;
        for (size_t i = 0; i < s.size(); ++i)
            worst = std::max({worst, std::fabs(s.k1[i] * 1.5 - 1), std::fabs(s.k2[i] * 1.5 - 1)});
        INFO("max relative error " << worst);
        CHECK(worst < 2e-4);
    }
}

TEST_CASE("On clean irregular meshes the jet is the most accurate estimator, curvature and C", "[estimators][lab]") {
    // Measured (jet curvature, C): torus 0.0088%, 0.30% (next best: rusinkiewicz 4.6%, 120%);
    // ellipsoid 0.0033%, 0.45%; cubic patch 0.0018%, 0.14%. The figures for a
    // CGAL 2-ring degree-4 jet: 0.015%/0.7%, 0.007%/0.6%, 0.02%/0.2%.
    const AnalyticMesh meshes[] = {test::analytic_torus(1, 0.4, 200, 100, 0.3, 101),
                                   test::analytic_ellipsoid(1, 0.7, 0.5, 6, 0.25, 201),
                                   test::analytic_cubic_patch(140, 0.1, 0.3, 0.7, 301)};
    for (const AnalyticMesh& a : meshes) {
        const Errors jet = errors(fields(a.mesh, Estimator::jet), a);
        INFO("jet: curvature " << jet.curvature << ", C " << jet.dcurv);
        CHECK(jet.curvature < 2e-4);
        CHECK(jet.dcurv < 0.01);
        // The configuration of the CGAL figures, degree 4 on the
        // 2-ring, on the same mesh: measured 2.4 to 8 times less accurate.
        const Errors cgal_like = errors(estimate_jet(test::estimator_inputs(a.mesh).of(a.mesh), jet_options(4, 2)), a);
        INFO("degree 4, 2-ring: curvature " << cgal_like.curvature << ", C " << cgal_like.dcurv);
        CHECK(jet.curvature < cgal_like.curvature);
        CHECK(jet.dcurv < cgal_like.dcurv);
        for (const std::string& name : estimator_names()) {
            const Estimator e = *parse_estimator(name);
            if (e == Estimator::jet) continue;
            const Errors other = errors(fields(a.mesh, e), a);
            INFO(name << ": curvature " << other.curvature << ", C " << other.dcurv);
            CHECK(other.curvature > 10 * jet.curvature);
            CHECK(other.dcurv > 10 * jet.dcurv);
        }
    }
}

TEST_CASE("With noise the jet grows its rings: no worse than a 3-ring jet", "[estimators][jet][noise]") {
    // 2% of the median edge along the normal (the criterion); measured
    // curvature error: adaptive (5 rings) 0.094, 3-ring 0.40, 2-ring 1.5.
    const AnalyticMesh a = test::with_normal_noise(test::analytic_torus(1, 0.4, 200, 100, 0.3, 7), 0.02, 8);
    const test::EstimatorInputs in = test::estimator_inputs(a.mesh);
    const Errors adaptive = errors(estimate_jet(in.of(a.mesh)), a);
    const Errors fixed = errors(estimate_jet(in.of(a.mesh), jet_options(4, 3)), a);
    INFO("adaptive " << adaptive.curvature << " / " << adaptive.dcurv << ", 3-ring " << fixed.curvature << " / "
                     << fixed.dcurv);
    CHECK(adaptive.curvature <= fixed.curvature);
    CHECK(adaptive.dcurv <= fixed.dcurv);
    CHECK(jet_plan_for_noise(0.0f).degree == 5);
    CHECK(jet_plan_for_noise(0.02f).rings == 5);
}

TEST_CASE("The jet's fallbacks are flagged and finite", "[estimators][jet]") {
    // A lone triangle: 3 points cannot carry even a quadratic jet.
    Mesh tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.faces = {{0, 1, 2}};
    const SurfaceFields s = fields(tri, Estimator::jet);
    for (size_t v = 0; v < 3; ++v) {
        CHECK((s.flags[v] & kFlagFallback));
        CHECK(s.k1[v] == 0.0f);
        CHECK(s.k2[v] == 0.0f);
    }
    // A small grid: vertices next to the border grow their rings and keep
    // degree 4; some border vertices fall back to degree 3 (flagged); the
    // plane's curvature is 0 everywhere.
    const SurfaceFields g = fields(make_grid(1.0f, 6), Estimator::jet);
    for (size_t v = 0; v < g.size(); ++v) {
        if (!(g.flags[v] & kFlagBoundary)) CHECK(!(g.flags[v] & kFlagFallback));
        CHECK(g.k1[v] == Approx(0.0f).margin(1e-5));
        CHECK(g.k2[v] == Approx(0.0f).margin(1e-5));
    }
}

TEST_CASE("Every estimator's error is bounded from above (not only compared with the jet's)", "[estimators][lab]") {
    // An estimator that returned zero curvature (relative error 1) or the
    // wrong sign (2) passes "worse than the jet and finite". Bounds: the
    // accuracy table (docs/accuracy/table.md, a mean over trials) measured
    // here on one mesh (printed by INFO, 2026-11-26), with margins of about 1.5x.
    struct Bound {
        const char* name;
        double curvature, dcurv;
    };
    // Clean uniform torus: every estimator is accurate. Measured (curvature, C):
    // rusinkiewicz 0.038%, 0.21%; tensor-averaging 0.063%, 0.24%; normal-fit
    // 0.064%, 0.26%; points-normals-fit 0.18%, 0.20%; jet 0.0086%, 0.18%.
    const AnalyticMesh uniform = test::analytic_torus(1, 0.4, 200, 100);
    for (const Bound& b : {Bound{"rusinkiewicz", 6e-4, 3.2e-3}, Bound{"tensor-averaging", 1e-3, 3.6e-3},
                           Bound{"normal-fit", 1e-3, 4e-3}, Bound{"points-normals-fit", 2.8e-3, 3e-3},
                           Bound{"jet", 1.3e-4, 2.7e-3}}) {
        const Errors e = errors(fields(uniform.mesh, *parse_estimator(b.name)), uniform);
        INFO("uniform torus, " << b.name << ": curvature " << e.curvature << ", C " << e.dcurv);
        CHECK(e.curvature < b.curvature);
        CHECK(e.dcurv < b.dcurv);
    }
    // Irregular torus (jitter 0.3): curvature errors far below 1, the error
    // of k = 0. Measured: rusinkiewicz 4.6%, tensor-averaging 25%,
    // normal-fit 11%, points-normals-fit 8.9%. C errors exceed 100% there
    // (120% to 900%), so only curvature is bounded.
    const AnalyticMesh irregular = test::analytic_torus(1, 0.4, 200, 100, 0.3, 101);
    for (const Bound& b : {Bound{"rusinkiewicz", 0.07, 0}, Bound{"tensor-averaging", 0.38, 0},
                           Bound{"normal-fit", 0.17, 0}, Bound{"points-normals-fit", 0.13, 0}}) {
        const Errors e = errors(fields(irregular.mesh, *parse_estimator(b.name)), irregular);
        INFO("irregular torus, " << b.name << ": curvature " << e.curvature << ", C " << e.dcurv);
        CHECK(e.curvature < b.curvature);
    }
}

TEST_CASE("On clean uniform meshes the jet beats a degree-4 2-ring jet (CGAL's configuration)", "[estimators][jet]") {
    // CGAL's Monge_via_jet_fitting (degree 4, 2-ring; bench/cgal_jet_estimate.h)
    // equals kappa's degree-4 2-ring jet to 3 digits on these meshes (accuracy
    // lab, 2026-11-27), so the fixed jet stands in for CGAL here. Measured
    // ratios jet / fixed (curvature, C): unit icosphere level 5 0.68, 0.61;
    // torus 200 x 100 0.87, 0.23; torus 100 x 50 (coarse: the 2-ring's fit
    // wins the choice) 0.24, 0.25. Before the choice between rings (issue 25)
    // they were 0.31, 1.42; 1.02, 0.25; 2.5, 2.0.
    struct Case {
        const char* name;
        AnalyticMesh mesh;
        double curvature, dcurv;  // bounds on the ratios
    };
    const Case cases[] = {
        {"icosphere 5", test::analytic_ellipsoid(1, 1, 1, 5), 0.85, 0.8},
        {"torus 200 x 100", test::analytic_torus(1, 0.4, 200, 100), 0.95, 0.4},
        {"torus 100 x 50", test::analytic_torus(1, 0.4, 100, 50), 0.5, 0.5},
    };
    for (const Case& c : cases) {
        const test::EstimatorInputs in = test::estimator_inputs(c.mesh.mesh);
        const Errors jet = errors(estimate_jet(in.of(c.mesh.mesh)), c.mesh);
        const Errors fixed = errors(estimate_jet(in.of(c.mesh.mesh), jet_options(4, 2)), c.mesh);
        INFO(c.name << ": jet " << jet.curvature << " / " << jet.dcurv << ", degree 4 on the 2-ring "
                    << fixed.curvature << " / " << fixed.dcurv);
        CHECK(jet.curvature < c.curvature * fixed.curvature);
        CHECK(jet.dcurv < c.dcurv * fixed.dcurv);
    }
}

TEST_CASE("The jet gives the same bits whatever the thread count, clean and noisy", "[estimators][jet][determinism]") {
    // Clean: the noise sample's fits serve as the plan's own fits for the
    // sampled vertices. Noisy (2% of an edge): the first look at the sample
    // settles the plan. 20k vertices: several chunks per thread.
    for (const double noise : {0.0, 0.02}) {
        const AnalyticMesh a = test::with_normal_noise(test::analytic_torus(1, 0.4, 200, 100, 0.3, 7), noise, 8);
        const test::EstimatorInputs in = test::estimator_inputs(a.mesh);
        INFO("noise " << noise);
        set_thread_count(1);
        const CurvatureEstimate one = estimate_jet(in.of(a.mesh));
        for (unsigned threads : {2u, 5u}) {
            set_thread_count(threads);
            const CurvatureEstimate other = estimate_jet(in.of(a.mesh));
            CHECK(std::memcmp(one.normals.data(), other.normals.data(), one.normals.size() * sizeof(glm::vec3)) == 0);
            CHECK(std::memcmp(one.tensors.tensor.data(), other.tensors.tensor.data(),
                              one.tensors.tensor.size() * sizeof(Tensor2)) == 0);
            CHECK(std::memcmp(one.dcurv_uv.data(), other.dcurv_uv.data(), one.dcurv_uv.size() * sizeof(glm::vec4)) == 0);
            CHECK(one.flags == other.flags);
        }
        set_thread_count(0);
    }
}
