// Per-stage timings of the curvature pipeline: load, adjacency, normals,
// areas, curvature, C, write (PLY). Median of repeated runs.
//
//   build/bench_curvature [MESH] [--runs N] [--threads N] [--out FILE.ply]
//
// Default MESH: ../shared/meshes/bunny-1M.ply next to the repository.
#include "median.h"

#include "bench_mesh.h"
#include "geometry/io/mesh_io.h"
#include "geometry/parallel/parallel.h"
#include "geometry/surface_analysis.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace kappa;

using kappa::bench::median;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

}  // namespace

int main(int argc, char** argv) {
    std::string path = std::string(KAPPA_SOURCE_DIR) + "/../shared/meshes/bunny-1M.ply";
    std::string out = "/tmp/kappa-bench-curvature.ply";
    int runs = 11;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) runs = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) set_thread_count(unsigned(std::atoi(argv[++i])));
        else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) out = argv[++i];
        else path = argv[i];
    }
    const char* names[] = {"load", "adjacency", "normals", "areas", "curvature", "dcurv", "write", "compute", "total"};
    std::vector<std::vector<double>> t(9);
    size_t nv = 0, nf = 0;
    for (int r = 0; r < runs; ++r) {
        const double t0 = now();
        const Mesh mesh = bench::load_or_exit(path);
        const double t1 = now();
        StageTimes st;
        const SurfaceFields fields = compute_surface_fields(mesh, {}, &st);
        const double t2 = now();
        write_ply(out, mesh, fields, true);
        const double t3 = now();
        nv = mesh.vertex_count();
        nf = mesh.face_count();
        const double row[] = {t1 - t0, st.adjacency, st.normals, st.areas, st.curvature, st.dcurv, t3 - t2, t2 - t1, t3 - t0};
        for (int k = 0; k < 9; ++k) t[k].push_back(row[k]);
    }
    std::printf("%s: %zu vertices, %zu faces, %d runs, %u threads\n", path.c_str(), nv, nf, runs, thread_count());
    std::printf("%-10s %10s %10s %10s\n", "stage", "median ms", "min ms", "max ms");
    for (int k = 0; k < 9; ++k)
        std::printf("%-10s %10.1f %10.1f %10.1f\n", names[k], 1e3 * median(t[k]),
                    1e3 * *std::min_element(t[k].begin(), t[k].end()), 1e3 * *std::max_element(t[k].begin(), t[k].end()));
    std::remove(out.c_str());
    return 0;
}
