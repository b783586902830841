// Topology and statistics timings (what `kappa info` does before curvature):
// edge table, full topology, all statistics, and the built-in model. Prints
// every run and the median.
//
//   bench_topology [MESH] [RUNS]   (default: ../shared/meshes/bunny-1M.ply next to the repo, 11 runs)
#include "time_it.h"

#include "geometry/mesh/default_model.h"
#include "geometry/mesh/edge_table.h"
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/mesh_stats.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/parallel/parallel.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using kappa::bench::time_it;

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
