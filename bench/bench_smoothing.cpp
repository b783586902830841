// Noise estimate and automatic smoothing (SmoothingOptions::automatic) on
// bunny.ply and bunny-1M.ply: the noise-level estimate alone, then the whole
// compute_surface_fields with the auto widths, split into smoothing (noise
// estimate included) and the rest. Medians of repeated runs.
//
//   build/bench_smoothing [--runs N] [--threads N] [MESH...]
#include "time_it.h"

#include "geometry/curvature/face_geometry.h"
#include "geometry/io/mesh_io.h"
#include "geometry/curvature/vertex_basics.h"
#include "geometry/parallel/parallel.h"
#include "geometry/scale/noise_level.h"
#include "geometry/surface_analysis.h"
#include "geometry/mesh/vertex_faces.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace kappa;

int main(int argc, char** argv) {
    const std::string dir = std::string(KAPPA_SOURCE_DIR) + "/../shared/meshes/";
    std::vector<std::string> paths;
    int runs = 5;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) runs = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) set_thread_count(unsigned(std::atoi(argv[++i])));
        else paths.push_back(argv[i]);
    }
    if (paths.empty()) paths = {dir + "bunny.ply", dir + "bunny-1M.ply"};
    std::printf("%u threads, %d runs\n", thread_count(), runs);
    for (const std::string& path : paths) {
        const Mesh mesh = load_mesh(path);
        const VertexFaces vf = build_vertex_faces(mesh);
        const std::vector<glm::vec3> normals = compute_vertex_basics(vf, compute_face_geometry(mesh)).normals;
        SmoothingOptions automatic;
        automatic.automatic = true;
        const SurfaceFields f = compute_surface_fields(mesh, automatic);
        std::printf("%s: %zu vertices; noise %.4g median edges; auto widths %.4g %.4g %.4g (%.3g %.3g %.3g edges)\n",
                    path.c_str(), mesh.vertex_count(), f.noise.relative, f.smoothing.normals, f.smoothing.curvature,
                    f.smoothing.dcurv, f.smoothing.normals / f.noise.median_edge,
                    f.smoothing.curvature / f.noise.median_edge, f.smoothing.dcurv / f.noise.median_edge);
        bench::time_it("noise estimate", runs, [&] { estimate_noise_level(mesh, vf, normals); }, 28);
        std::vector<double> smoothing, rest;
        bench::time_it("fields with auto smoothing", runs, [&] {
            StageTimes t;
            compute_surface_fields(mesh, automatic, &t);
            smoothing.push_back(1000 * t.smoothing);
            rest.push_back(1000 * (t.total() - t.smoothing));
        }, 28);
        std::printf("%-28s median %.1f ms smoothing (noise estimate included), %.1f ms the rest\n", "",
                    bench::median(smoothing), bench::median(rest));
    }
}
