// Topology and statistics timings (what `kappa info` does before curvature):
// edge table, full topology, all statistics, and the built-in model. Prints
// every run and the median.
//
//   bench_topology [MESH] [RUNS]   (default: ../shared/meshes/bunny-1M.ply next to the repo, 11 runs)
#include "median.h"

#include "geometry/default_model.h"
#include "geometry/edge_table.h"
#include "geometry/io/mesh_io.h"
#include "geometry/mesh_stats.h"
#include "geometry/mesh_topology.h"
#include "geometry/parallel.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

using Clock = std::chrono::steady_clock;

using kappa::bench::median;

namespace {

// Runs `body` once untimed (warm-up), then `runs` timed times; prints each
// wall time, then the medians of wall time and of process CPU time (all
// threads; less sensitive to other load on a shared machine).
void time_it(const char* label, int runs, const std::function<void()>& body) {
    body();
    std::vector<double> ms, cpu_ms;
    std::printf("%-24s", label);
    for (int r = 0; r < runs; ++r) {
        const auto t0 = Clock::now();
        const std::clock_t c0 = std::clock();
        body();
        cpu_ms.push_back(1000.0 * double(std::clock() - c0) / CLOCKS_PER_SEC);
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        std::printf(" %.1f", ms.back());
    }
    std::printf("  | median %.2f ms wall, %.2f ms cpu\n", median(ms), median(cpu_ms));
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    const std::filesystem::path source_dir = std::filesystem::path(__FILE__).parent_path().parent_path();
    const std::string path =
        argc > 1 ? argv[1] : (source_dir / ".." / "shared" / "meshes" / "bunny-1M.ply").string();
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 11;
    const kappa::Mesh mesh = kappa::load_mesh(path);
    std::printf("%s: %zu vertices, %zu faces, %u threads\n", path.c_str(), mesh.vertex_count(), mesh.face_count(),
                kappa::thread_count());

    const kappa::EdgeTable edges = kappa::build_edge_table(mesh);
    time_it("edge table", runs, [&] { kappa::build_edge_table(mesh); });
    time_it("topology (given edges)", runs, [&] { kappa::analyze_topology(mesh, edges); });
    time_it("all statistics", runs, [&] { kappa::compute_mesh_stats(mesh); });
    time_it("built-in model", runs, [&] { kappa::make_default_model(); });
    return 0;
}
