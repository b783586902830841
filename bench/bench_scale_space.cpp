// Cost of the scale space (geometry/scale/scale_space.h) next to the raw
// estimate it starts from: clusters and fits per level, and per-vertex fields for
// one view. Medians of repeated runs.
//
//   build/bench_scale_space [MESH] [--runs N] [--threads N] [--detail PX]
//
// Default MESH: ../shared/meshes/bunny-1M.ply next to the repository; the
// view frames the mesh from +z at 1024x768 (kappa render's default camera).
#include "time_it.h"

#include "geometry/io/mesh_io.h"
#include "geometry/parallel.h"
#include "geometry/scale/pixel_scale.h"
#include "geometry/scale/scale_space.h"
#include "geometry/surface_analysis.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace kappa;

int main(int argc, char** argv) {
    std::string path = std::string(KAPPA_SOURCE_DIR) + "/../shared/meshes/bunny-1M.ply";
    int runs = 7;
    float detail = 4;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) runs = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) set_thread_count(unsigned(std::atoi(argv[++i])));
        else if (!std::strcmp(argv[i], "--detail") && i + 1 < argc) detail = float(std::atof(argv[++i]));
        else path = argv[i];
    }
    const Mesh mesh = load_mesh(path);
    std::printf("%s: %zu vertices, %zu faces, %u threads, detail %g px\n", path.c_str(), mesh.vertex_count(),
                mesh.face_count(), thread_count(), detail);

    // kappa render's default camera: the bounding sphere framed from +z, fov 30, 1024x768.
    glm::vec3 lo = mesh.positions[0], hi = lo;
    for (const auto& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::vec3 center = 0.5f * (lo + hi);
    float radius = 0;
    for (const auto& p : mesh.positions) radius = std::max(radius, glm::length(p - center));
    const float fov = 30, distance = radius / std::sin(glm::radians(0.5f * fov));
    const glm::mat4 view = glm::lookAt(center + glm::vec3(0, 0, distance), center, glm::vec3(0, 1, 0));

    SurfaceFields raw;
    ScaleSpace space;
    std::vector<float> sigma;
    bench::time_it("raw fields", runs, [&] { raw = compute_surface_fields(mesh); });
    space = build_scale_space(mesh);
    for (size_t l = 0; l < space.levels.size(); ++l) {
        char label[48];
        std::snprintf(label, sizeof label, "level %zu clusters", l);
        bench::time_it(label, runs, [&] {
            space.clusters[l] = build_surface_clusters(mesh, raw.point_areas, raw.normals, space.origin,
                                                       space.level_scale(l));
        });
    }
    std::printf("  %zu levels:", space.levels.size());
    for (const auto& l : space.clusters) std::printf(" %zu", l.size());
    std::printf(" clusters\n");
    bench::time_it("build and fit all", runs, [&] {
        space = build_scale_space(mesh);
        fit_all_levels(mesh, space, raw);
    });
    bench::time_it("pixel sizes", runs, [&] {
        sigma = pixel_sizes(mesh, view, fov, 768);
        for (float& s : sigma) s *= detail;
    });
    bench::time_it("fields at scale (fresh)", runs, [&] {
        space = build_scale_space(mesh);
        (void)fields_at_scale(mesh, space, raw, sigma);
    });
    bench::time_it("fields at scale (fitted)", runs, [&] { (void)fields_at_scale(mesh, space, raw, sigma); });
    bench::time_it("normals at scale", runs, [&] { (void)normals_at_scale(mesh, space, raw, sigma); });
    return 0;
}
