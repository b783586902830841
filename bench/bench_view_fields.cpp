// What a new view costs with --detail (issue 30, item 3: "detail fields for a
// new view in at most twice the curvature job's time"), without GL: each
// stage of render/fields/detail_fields.h and the upload's CPU half
// (render/fields/field_upload.h), then the whole of it for the first view
// (the scale space's levels fitted on demand) and for later views (levels
// fitted), next to the curvature job (compute_surface_fields, as
// `kappa curvature` runs it). Each later view is the previous one turned
// 10 degrees about the model's up axis, as an orbit in the viewer: without and
// then with the levels' values at the vertices kept, as the viewer keeps them
// from its second view on.
// Medians of wall and process CPU time (time_it.h).
//
//   build/bench_view_fields [MESH] [--runs N] [--threads N] [--detail PX] [--size WxH] [--views-only]
//
// --views-only: the curvature job, the first view and the new views, without the stages.
//
// Default MESH: ../shared/meshes/bunny-1M.ply next to the repository; the
// camera is kappa's default view of the mesh.
#include "time_it.h"

#include "app/heap_tuning.h"

#include "geometry/culling/face_clusters.h"
#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/parallel/parallel.h"
#include "geometry/surface_analysis.h"
#include "render/camera/camera.h"
#include "render/fields/detail_fields.h"
#include "render/fields/field_upload.h"

#include <glm/trigonometric.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace kappa;

int main(int argc, char** argv) {
    kappa::app::keep_large_blocks();  // as kappa render and kappa view
    std::string path = std::string(KAPPA_SOURCE_DIR) + "/../shared/meshes/bunny-1M.ply";
    int runs = 5, width = 1024, height = 768;
    float detail = 12;  // RenderSettings::detail
    bool views_only = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) runs = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) set_thread_count(unsigned(std::atoi(argv[++i])));
        else if (!std::strcmp(argv[i], "--detail") && i + 1 < argc) detail = float(std::atof(argv[++i]));
        else if (!std::strcmp(argv[i], "--views-only")) views_only = true;
        else if (!std::strcmp(argv[i], "--size") && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &width, &height);
        else path = argv[i];
    }
    const Mesh mesh = load_mesh(path);
    std::printf("%s: %zu vertices, %zu faces, %u threads, detail %g px, %dx%d\n", path.c_str(), mesh.vertex_count(),
                mesh.face_count(), thread_count(), detail, width, height);

    const render::BoundingSphere sphere = render::bounding_sphere(mesh);
    render::Camera camera = render::Camera::default_view(mesh, sphere, 30, float(width) / float(height));
    const glm::vec3 up = glm::vec3(glm::inverse(camera.view) * glm::vec4(0, 1, 0, 0));
    auto next_view = [&] { camera = camera.orbited(sphere.center, up, glm::radians(10.0f)); };

    const VertexFaces adjacency = build_vertex_faces(mesh);
    const FaceClusters clusters = cluster_faces(mesh, 256);  // as render/fields/mesh_buffers.cpp
    SurfaceFields raw;
    bench::time_it("curvature job", runs, [&] { raw = compute_surface_fields(mesh); });

    render::DetailSource source;
    if (views_only) source = render::make_detail_source(mesh, raw, &adjacency);
    else bench::time_it("detail source", runs, [&] { source = render::make_detail_source(mesh, raw, &adjacency); });
    if (!views_only) {
        render::ViewScales scales;
        bench::time_it("view scales", runs, [&] {
            scales = render::view_scales(mesh, source, camera, height, detail);
        });
        // Fit every level the view needs once, so the rows below time the per-vertex blends.
        render::DetailFields view = render::detail_fields(mesh, source, raw, scales);
        bench::time_it("fine normals", runs, [&] { (void)normals_at_scale(mesh, source.space, raw, scales.fine); });
        bench::time_it("fields at scale", runs, [&] { view.fields = fields_at_scale(mesh, source.space, raw, scales.sigma); });
        bench::time_it("feature size", runs, [&] { (void)feature_size(mesh, view.fields); });
        bench::time_it("upload, CPU half", runs, [&] {
            (void)render::prepare_field_upload(view.mesh, view.fields, view.feature_size, view.fine_normals, clusters);
        });
    }

    bench::time_it("first view (levels fit)", runs, [&] {
        render::DetailSource fresh = render::make_detail_source(mesh, raw, &adjacency);
        const render::DetailFields d = render::detail_fields(mesh, fresh, raw, camera, height, detail);
        (void)render::prepare_field_upload(d.mesh, d.fields, d.feature_size, d.fine_normals, clusters);
    });
    if (views_only) (void)render::detail_fields(mesh, source, raw, camera, height, detail);  // the levels it needs
    auto new_view = [&] {
        next_view();
        const render::DetailFields d = render::detail_fields(mesh, source, raw, camera, height, detail);
        (void)render::prepare_field_upload(d.mesh, d.fields, d.feature_size, d.fine_normals, clusters);
    };
    // Without, then (as app/mesh_drawing.cpp from its second view on) with the levels' values at the
    // vertices kept (geometry/scale/level_value_cache.h): filled by one view, read by the next ones.
    // Twice, alternating, as the views turn on.
    for (int round = 0; round < 2; ++round) {
        source.space.keep_level_values(false);
        bench::time_it("new view (levels fitted)", runs, new_view);
        source.space.keep_level_values(true);
        bench::time_it("  the view that keeps them", 1, new_view);
        bench::time_it("new view (values kept)", runs, new_view);
        std::printf("  values kept: %.0f MB\n",
                    double(source.space.tensor_values.bytes() + source.space.surface_values.bytes()) / 1e6);
    }
    return 0;
}
