// The accuracy lab: the paper's Fig. 8 (Rusinkiewicz 2004) for every
// estimator, from exact analytic truth (tests/analytic_curvature.h).
//
//   build/accuracy_lab [--trials N] [--quick] [--max-noise X] [--out FILE.csv]
//                      [--surface TEXT] [--method TEXT]   (only those whose names contain TEXT)
//
// Surfaces: a unit sphere (icosphere level 5, 10k vertices; uniform), a
// torus (R 1, r 0.4, 200 x 100 = 20k vertices) with a uniform
// and an irregular tessellation (every vertex moved by up to 0.3 cells in
// each angle, on the surface), a randomly tessellated ellipsoid (1, 0.7,
// 0.5; icosphere level 6, 41k vertices, moved by up to 0.25 of an edge and
// projected back), and random cubic height patches over [-1, 1]^2
// (coefficients in [-0.1, 0.1], a 141^2 grid jittered by up to 0.3 cells,
// errors measured on the inner 70%). Larger jitter folds triangles (the
// vertex normal then flips), which no estimator is meant to survive.
// --quick: a quarter of the vertices. Noise: Gaussian displacement along the
// true normal with sigma = 0..10% of the median edge length, errors averaged
// over `trials` noise draws (and over patches for the cubic). Methods: the
// five estimators, rusinkiewicz and jet with --smooth auto, two fixed
// jets for reference: degree 4 on the 2-ring (the configuration of CGAL's
// figures in issue 10) and on the 3-ring (the criterion with
// noise); and the public estimators: CGAL's jet, degree 4 on the 2-ring
// (cgal_jet_estimate.h; only where CMake found CGAL and Eigen), and a
// reference of libigl's principal_curvature over a ball of 5 mean edges
// (igl_quadric_reference.h, written for this lab; no C). Errors: curvature
// as in Fig. 8 (RMS normal-curvature error over directions and vertices
// over the RMS normal curvature), C as the RMS norm of the error tensor
// over the RMS |C| (on the sphere, where C = 0, over the RMS squared
// curvature: tests/analytic_curvature.h, dcurv_reference2). Writes one CSV
// row per (surface, noise, method), names quoted (C error nan where a
// method gives no C):
//   surface,noise,method,curvature_error,dcurv_error
// scripts/accuracy-lab.sh runs it and plots the CSV (scripts/plot_accuracy.py).
#include "igl_quadric_reference.h"
#ifdef KAPPA_HAVE_CGAL
#include "cgal_jet_estimate.h"
#endif
#include "tests/analytic_estimate.h"

#include "geometry/curvature/jet.h"

#include "geometry/parallel/parallel.h"
#include "geometry/surface_analysis.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

using namespace kappa;
using test::AnalyticMesh;

namespace {

// One curve: a name and the errors it makes on a mesh.
struct Method {
    std::string name;
    std::function<test::RelativeErrors(const AnalyticMesh&)> errors;
};

Method pipeline(const std::string& name, const SmoothingOptions& o) {
    return {name, [o](const AnalyticMesh& a) {
                const SurfaceFields f = compute_surface_fields(a.mesh, o);
                return test::RelativeErrors{test::relative_curvature_error(f, a), test::relative_dcurv_error(f, a)};
            }};
}

// A jet with a fixed degree and ring, as a reference: degree 4 on the
// 2-ring is the configuration of the CGAL figures.
Method fixed_jet(int degree, int rings) {
    JetOptions o;
    o.degree = degree;
    o.rings = rings;
    return {"jet, degree " + std::to_string(degree) + ", " + std::to_string(rings) + "-ring",
            [o](const AnalyticMesh& a) {
                const test::EstimatorInputs in = test::estimator_inputs(a.mesh);
                return test::relative_errors(estimate_jet(in.of(a.mesh), o), a);
            }};
}

// An estimator outside the pipeline, run on the Max normals and areas
// (public references: CGAL's jet, libigl's quadric).
Method reference(const std::string& name, std::function<CurvatureEstimate(const Mesh&, const test::EstimatorInputs&)> run) {
    return {name, [run](const AnalyticMesh& a) {
                const test::EstimatorInputs in = test::estimator_inputs(a.mesh);
                return test::relative_errors(run(a.mesh, in), a);
            }};
}

std::vector<Method> methods() {
    std::vector<Method> out;
    for (const std::string& name : estimator_names()) {
        SmoothingOptions o;
        o.estimator = *parse_estimator(name);
        out.push_back(pipeline(name, o));
    }
    SmoothingOptions automatic;
    automatic.automatic = true;
    out.push_back(pipeline("rusinkiewicz --smooth auto", automatic));
    automatic.estimator = Estimator::jet;
    out.push_back(pipeline("jet --smooth auto", automatic));
    out.push_back(fixed_jet(4, 2));
    out.push_back(fixed_jet(4, 3));
#ifdef KAPPA_HAVE_CGAL
    out.push_back(reference("CGAL jet, degree 4, 2-ring", [](const Mesh& m, const test::EstimatorInputs& in) {
        return bench::cgal_jet_estimate(m, in.vf, in.normals);
    }));
#endif
    out.push_back(reference("libigl quadric, 5-edge ball (reference)", [](const Mesh& m, const test::EstimatorInputs& in) {
        return bench::igl_quadric_reference(m, in.vf, in.faces, 5);
    }));
    return out;
}

struct Surface {
    std::string name;
    std::function<AnalyticMesh(int trial)> make;  // the clean mesh of a trial
};

}  // namespace

int main(int argc, char** argv) {
    int trials = 3;
    bool quick = false;
    double max_noise = 1;
    std::string out_path = "accuracy.csv";
    std::string only_surface, only_method;  // substrings; empty: all
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--trials") && i + 1 < argc) trials = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--quick")) quick = true;
        else if (!std::strcmp(argv[i], "--max-noise") && i + 1 < argc) max_noise = std::atof(argv[++i]);
        else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) out_path = argv[++i];
        else if (!std::strcmp(argv[i], "--surface") && i + 1 < argc) only_surface = argv[++i];
        else if (!std::strcmp(argv[i], "--method") && i + 1 < argc) only_method = argv[++i];
        else {
            std::fprintf(stderr, "usage: accuracy_lab [--trials N] [--quick] [--max-noise X] [--out FILE.csv] "
                                 "[--surface TEXT] [--method TEXT]\n");
            return 2;
        }
    }
    const int s = quick ? 2 : 1;  // --quick: a quarter of the vertices
    const std::vector<Surface> surfaces = {
        {"sphere, uniform", [&](int) { return test::analytic_ellipsoid(1, 1, 1, quick ? 4 : 5); }},
        {"torus, uniform", [&](int) { return test::analytic_torus(1, 0.4, 200 / s, 100 / s); }},
        {"torus, irregular", [&](int t) { return test::analytic_torus(1, 0.4, 200 / s, 100 / s, 0.3, 100 + t); }},
        {"ellipsoid, random", [&](int t) { return test::analytic_ellipsoid(1, 0.7, 0.5, quick ? 5 : 6, 0.25, 200 + t); }},
        {"cubic patches", [&](int t) { return test::analytic_cubic_patch(140 / s, 0.1, 0.3, 0.7, 300 + t); }},
    };
    const double noises[] = {0, 0.01, 0.02, 0.03, 0.05, 0.07, 0.1};
    std::vector<Method> ms = methods();
    ms.erase(std::remove_if(ms.begin(), ms.end(),
                            [&](const Method& m) { return m.name.find(only_method) == std::string::npos; }),
             ms.end());

    FILE* out = std::fopen(out_path.c_str(), "w");
    if (!out) {
        std::fprintf(stderr, "accuracy_lab: cannot write %s\n", out_path.c_str());
        return 1;
    }
    std::fprintf(out, "surface,noise,method,curvature_error,dcurv_error\n");
    const auto t0 = std::chrono::steady_clock::now();
    for (const Surface& surface : surfaces) {
        if (surface.name.find(only_surface) == std::string::npos) continue;
        for (double noise : noises) {
            if (noise > max_noise) continue;
            std::vector<double> ek(ms.size(), 0), ec(ms.size(), 0);
            const bool uniform = surface.name.find("uniform") != std::string::npos;  // one clean mesh
            const int n = noise > 0 || !uniform ? trials : 1;
            for (int t = 0; t < n; ++t) {
                const AnalyticMesh clean = surface.make(t);
                const AnalyticMesh a = noise > 0 ? test::with_normal_noise(clean, noise, 1000 + t) : clean;
                for (size_t m = 0; m < ms.size(); ++m) {
                    const test::RelativeErrors e = ms[m].errors(a);
                    ek[m] += e.curvature / n;
                    ec[m] += e.dcurv / n;
                }
            }
            for (size_t m = 0; m < ms.size(); ++m) {
                std::fprintf(out, "\"%s\",%g,\"%s\",%.6g,%.6g\n", surface.name.c_str(), noise, ms[m].name.c_str(),
                             ek[m], ec[m]);
                std::printf("%-18s noise %4.2f  %-26s curvature %10.6f  C %10.6f\n", surface.name.c_str(), noise,
                            ms[m].name.c_str(), ek[m], ec[m]);
            }
            std::fflush(stdout);
        }
    }
    std::fclose(out);
    std::printf("wrote %s in %.1f s\n", out_path.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    return 0;
}
