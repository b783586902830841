// compute_surface_fields with each curvature estimator (all stages: normals,
// areas, flags, curvature, C), median of repeated runs, wall and CPU time.
//
//   build/bench_estimators [MESH|torus] [--runs N] [--threads N] [--estimator NAME]
//
// Default MESH: ../shared/meshes/bunny-1M.ply next to the repository;
// `torus`: the accuracy lab's clean irregular torus (20k vertices), the
// size of the CGAL figure (1.2 s on one core). Default: every
// estimator. The targets: jet on bunny-1M in at most 2 s on 2
// threads, and 10x CGAL's time per vertex.
#include "bench_mesh.h"
#include "time_it.h"

#include "geometry/parallel/parallel.h"
#include "geometry/surface_analysis.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace kappa;

int main(int argc, char** argv) {
    std::string path = std::string(KAPPA_SOURCE_DIR) + "/../shared/meshes/bunny-1M.ply";
    int runs = 5;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) runs = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) set_thread_count(unsigned(std::atoi(argv[++i])));
        else if (!std::strcmp(argv[i], "--estimator") && i + 1 < argc) only = argv[++i];
        else path = argv[i];
    }
    const Mesh mesh = bench::estimator_bench_mesh(path);
    std::printf("%s: %zu vertices, %zu faces, %d runs, %u threads\n", path.c_str(), mesh.vertex_count(),
                mesh.face_count(), runs, thread_count());
    for (const std::string& name : estimator_names()) {
        if (!only.empty() && name != only) continue;
        SmoothingOptions o;
        o.estimator = *parse_estimator(name);
        bench::time_it(name.c_str(), runs, [&] { compute_surface_fields(mesh, o); });
    }
    return 0;
}
