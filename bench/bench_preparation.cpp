// What drawing a mesh does between reading it and its fields (`kappa render`'s
// "load" less the read, app/mesh_drawing.cpp): drawing units, the inside-out
// test, the crease angle (auto), the creases, the split along them. Each stage
// timed alone on the loaded mesh, then all of them in order as MeshDrawing
// runs them, next to the read they should not outweigh (issue 30, item 3).
// Prints every run and the median.
//
//   bench_preparation [MESH] [RUNS]   (default: ../shared/meshes/bunny-1M.ply next to the repo, 5 runs)
#include "bench_mesh.h"
#include "time_it.h"

#include "geometry/io/mesh_io.h"
#include "geometry/mesh/creases.h"
#include "geometry/mesh/drawing_units.h"
#include "geometry/mesh/edge_bends.h"
#include "geometry/mesh/orientation.h"
#include "geometry/parallel/parallel.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

using kappa::bench::time_it;

int main(int argc, char** argv) {
    const std::filesystem::path source_dir = std::filesystem::path(__FILE__).parent_path().parent_path();
    const std::string path =
        argc > 1 ? argv[1] : (source_dir / ".." / "shared" / "meshes" / "bunny-1M.ply").string();
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
    const kappa::Mesh mesh = kappa::bench::load_or_exit(path);
    const float angle = kappa::auto_crease_angle(mesh);
    std::printf("%s: %zu vertices, %zu faces, %u threads; auto crease angle %g, %zu creases\n", path.c_str(),
                mesh.vertex_count(), mesh.face_count(), kappa::thread_count(), angle,
                kappa::find_creases(mesh, angle).size());

    time_it("read", runs, [&] { kappa::load_mesh(path); });
    time_it("drawing units", runs, [&] { kappa::drawing_units(mesh); });
    time_it("inside out", runs, [&] { kappa::is_inside_out(mesh); });
    time_it("  vertex faces", runs, [&] { kappa::build_vertex_faces(mesh); });
    time_it("  face normals", runs, [&] { kappa::face_normals(mesh); });
    const kappa::VertexFaces vf = kappa::build_vertex_faces(mesh);
    time_it("  edge bends (given vf)", runs, [&] { kappa::measure_edge_bends(mesh, vf, angle); });
    time_it("auto crease angle", runs, [&] { kappa::auto_crease_angle(mesh); });
    time_it("find creases", runs, [&] { kappa::find_creases(mesh, angle); });
    time_it("auto angle + creases", runs, [&] { kappa::resolve_creases(mesh, -1); });
    const auto creases = kappa::find_creases(mesh, angle);
    time_it("mesh copy", runs, [&] { kappa::Mesh copy = mesh; });
    time_it("copy + split", runs, [&] { kappa::split_at_creases(mesh, creases); });
    // As app/mesh_drawing.cpp: the copy stands for the mesh just read.
    time_it("copy + all of them", runs, [&] {
        kappa::Mesh m = mesh;
        const kappa::DrawingUnits units = kappa::drawing_units(m);
        kappa::to_drawing_units(m, units);
        if (kappa::is_inside_out(m)) kappa::flip_faces(m);
        const kappa::ResolvedCreases found = kappa::resolve_creases(m, -1);  // auto
        kappa::split_at_creases(std::move(m), found.creases);
    });
    return 0;
}
