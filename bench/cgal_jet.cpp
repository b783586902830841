// CGAL's Monge_via_jet_fitting (Cazals & Pouget 2003) at every vertex, one
// thread: the reference of issue 10's speed target for `--estimator jet`
// ("at least 10x faster per vertex than CGAL's"). Built only where CMake
// finds CGAL and Eigen (Debian: libcgal-dev libeigen3-dev); CI needs neither.
//
//   build/bench_cgal_jet [MESH|torus] [--runs N] [--kappa]
//
// MESH as bench_estimators (bench_mesh.h; default ../shared/meshes/bunny.ply).
// Timed, per vertex: its 2-ring and CGAL's fit with d_fitting = 4, d_monge =
// 3 (principal curvatures and directions and the third-order coefficients,
// i.e. C), as cgal_jet_estimate.h describes them. Not
// timed: loading or building the mesh and the adjacency. Like time_it: one
// warm-up, then N runs (default 1), median wall time and time per vertex.
//
// --kappa: also times kappa's estimate_jet on the same mesh, single-threaded,
// alternating with CGAL's run in every round (ratios: of the medians, and
// the median of each round's ratio, as ab-time.py): its default plan (noise
// estimate, degree and rings from it, adjacency build, refits) and fixed
// degree 4 on the 2-ring (CGAL's work). Its inputs (Max normals, areas) are
// built once, untimed.
#include "bench_mesh.h"
#include "cgal_jet_estimate.h"
#include "median.h"

#include "tests/analytic_estimate.h"

#include "geometry/curvature/jet.h"
#include "geometry/curvature/rings.h"
#include "geometry/parallel/parallel.h"
#include "geometry/mesh/vertex_faces.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

using namespace kappa;

namespace {

using bench::CgalKernel;
using bench::CgalMongeFit;
using bench::kCgalFitDegree;
using bench::kCgalMongeDegree;
using bench::kCgalPointsNeeded;

struct CgalResult {
    size_t skipped = 0;      // still fewer than kCgalPointsNeeded points at 4 rings
    double mean_k2 = 0;      // mean of k1^2 + k2^2 (orientation-free checksum)
    double mean_b2 = 0;      // mean of b0^2 + ... + b3^2 (third order)
    double mean_points = 0;  // fitted points per vertex
};

CgalResult cgal_fits(const Mesh& mesh, const VertexAdjacency& adj) {
    CgalResult r;
    const size_t nv = mesh.vertex_count();
    RingCollector rings(nv);
    std::vector<CgalKernel::Point_3> points;
    size_t fitted = 0, point_sum = 0;
    for (size_t v = 0; v < nv; ++v) {
        if (!bench::cgal_ring_points(mesh, adj, rings, uint32_t(v), points)) {
            ++r.skipped;
            continue;
        }
        CgalMongeFit fit;
        const CgalMongeFit::Monge_form m = fit(points.begin(), points.end(), kCgalFitDegree, kCgalMongeDegree);
        const double k1 = m.principal_curvatures(0), k2 = m.principal_curvatures(1);
        double b2 = 0;
        for (int i = 0; i < 4; ++i) b2 += m.third_order_coefficients(i) * m.third_order_coefficients(i);
        r.mean_k2 += k1 * k1 + k2 * k2;
        r.mean_b2 += b2;
        point_sum += points.size();
        ++fitted;
    }
    if (fitted) {
        r.mean_k2 /= double(fitted);
        r.mean_b2 /= double(fitted);
        r.mean_points = double(point_sum) / double(fitted);
    }
    return r;
}

struct Timed {
    const char* label;
    std::function<void()> body;
    std::vector<double> ms;
};

double wall_ms(const std::function<void()>& body) {
    const auto t0 = std::chrono::steady_clock::now();
    body();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
    std::string path = std::string(KAPPA_SOURCE_DIR) + "/../shared/meshes/bunny.ply";
    int runs = 1;
    bool with_kappa = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) runs = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--kappa")) with_kappa = true;
        else path = argv[i];
    }
    set_thread_count(1);
    const Mesh mesh = bench::estimator_bench_mesh(path);
    const size_t nv = mesh.vertex_count();
    const VertexFaces vf = build_vertex_faces(mesh);
    const VertexAdjacency adj = build_vertex_adjacency(mesh, vf);
    std::printf("%s: %zu vertices, %zu faces, %d runs, 1 thread\n", path.c_str(), nv, mesh.face_count(), runs);

    CgalResult cgal;
    std::vector<Timed> timed;
    timed.push_back({"CGAL jet, degree 4 (Monge 3), 2-ring", [&] { cgal = cgal_fits(mesh, adj); }, {}});
    test::EstimatorInputs inputs;
    if (with_kappa) {
        inputs = test::estimator_inputs(mesh);
        timed.push_back({"kappa jet, default plan", [&] { estimate_jet(inputs.of(mesh)); }, {}});
        JetOptions fixed;
        fixed.degree = 4;
        fixed.rings = 2;
        timed.push_back({"kappa jet, degree 4, 2-ring", [&, fixed] { estimate_jet(inputs.of(mesh), fixed); }, {}});
    }
    for (Timed& t : timed) t.body();  // warm-up
    for (int r = 0; r < runs; ++r)
        for (Timed& t : timed) t.ms.push_back(wall_ms(t.body));

    const double cgal_ms = bench::median(timed[0].ms);
    for (const Timed& t : timed) {
        std::printf("%-38s", t.label);
        for (double ms : t.ms) std::printf(" %.1f", ms);
        const double m = bench::median(t.ms);
        std::printf("  | median %.2f ms wall, %.3f us per vertex", m, 1000.0 * m / double(nv));
        if (&t != &timed[0] && m > 0) {
            std::vector<double> ratios;  // per round, as ab-time.py
            for (size_t r = 0; r < t.ms.size(); ++r) ratios.push_back(timed[0].ms[r] / t.ms[r]);
            std::printf(", CGAL / this: %.1fx medians, %.1fx median per round", cgal_ms / m, bench::median(ratios));
        }
        std::printf("\n");
    }
    size_t isolated = 0;
    for (size_t v = 0; v < nv; ++v) isolated += vf.degree(v) == 0;
    std::printf("CGAL: %zu vertices skipped (< %zu points in 4 rings; %zu of them in no face), %.1f points per fit, "
                "mean k1^2+k2^2 %.6g, mean |b|^2 %.6g\n",
                cgal.skipped, kCgalPointsNeeded, isolated, cgal.mean_points, cgal.mean_k2, cgal.mean_b2);
    return 0;
}
