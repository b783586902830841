// Cost of the scale space (geometry/scale/scale_space.h) next to the raw
// estimate it starts from: clusters and fits per level, and per-vertex fields for
// one view. Medians of repeated runs.
//
//   build/bench_scale_space [MESH] [--runs N] [--threads N] [--detail PX]
//
// Default MESH: ../shared/meshes/bunny-1M.ply next to the repository; the
// view frames the mesh from +z at 1024x768 (kappa render's default camera).
#include "time_it.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/io/ply_io.h"
#include "geometry/scale/auto_smoothing.h"
#include "geometry/scale/noise_level.h"
#include "geometry/mesh/vertex_faces.h"

#include "geometry/io/mesh_io.h"
#include "geometry/parallel/parallel.h"
#include "geometry/scale/pixel_scale.h"
#include "geometry/scale/scale_space.h"
#include "geometry/surface_analysis.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace kappa;

int main(int argc, char** argv) {
    std::string path = std::string(KAPPA_SOURCE_DIR) + "/../shared/meshes/bunny-1M.ply";
    int runs = 7;
    float detail = 12;  // RenderSettings::detail
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
    bench::time_it("surface at scale (positions too)", runs, [&] { (void)surface_at_scale(mesh, space, raw, sigma); });

    // The budget of issue 9: the fields of kappa render's default view at the
    // default detail (what render/fields/detail_fields.cpp does, without GL), against
    // what `kappa curvature MESH -o OUT.ply` does; alternating, same process.
    const std::string out_ply = "/tmp/kappa-bench-scale-space.ply";
    std::vector<double> with_detail, curvature_command, ratio;
    auto seconds = [](auto&& body) {
        const auto t0 = std::chrono::steady_clock::now();
        body();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    for (int r = 0; r < runs + 1; ++r) {
        const double a = seconds([&] {
            // As kappa render does (render/fields/detail_fields.cpp): normals first,
            // the raw curvature only if the view's scales blend it in.
            const Mesh m = load_mesh(path);
            SurfaceFields f = compute_surface_normals(m);
            ScaleSpace s = build_scale_space(m);
            const NoiseLevel noise = estimate_noise_level(m, build_vertex_faces(m), f.normals);
            const float floor = choose_smoothing_widths(noise).normals;
            std::vector<float> sg = pixel_sizes(m, view, fov, 768);
            for (float& x : sg) x = std::max(x * detail, floor);
            if (uses_raw_estimate(s, sg)) f = compute_surface_fields(m);
            const std::vector<glm::vec3> fine = normals_at_scale(m, s, f, std::vector<float>(m.vertex_count(), 0.0f));
            const SurfaceFields at = fields_at_scale(m, s, f, sg);
            (void)feature_size(m, at);
        });
        const double b = seconds([&] {
            const Mesh m = load_mesh(path);
            const SurfaceFields f = compute_surface_fields(m);
            write_ply(out_ply, m, f, true);
        });
        if (r == 0) continue;  // warm-up
        with_detail.push_back(a * 1e3);
        curvature_command.push_back(b * 1e3);
        ratio.push_back(a / b);
    }
    std::remove(out_ply.c_str());
    std::printf("load + fields + detail fields (default view): median %.1f ms\n", bench::median(with_detail));
    std::printf("load + fields + write PLY (kappa curvature):  median %.1f ms\n", bench::median(curvature_command));
    std::printf("ratio, median of pairs: %.2f\n", bench::median(ratio));
    return 0;
}
