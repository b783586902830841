// What drawing a mesh does between reading it and its fields (`kappa render`'s
// "load" less the read, app/mesh_drawing.cpp and app/mesh_source.cpp), and the
// default view it then takes (app/render_options.cpp, make_camera): drawing
// units, the crease angle (auto: a sampled vote), the passes over the faces
// (the inside-out volumes and the crease candidates), the creases around the
// candidates, the split along them, the bounding sphere. Each stage timed
// alone on the loaded mesh, then all of them as MeshDrawing runs them (the
// app's own prepare_for_drawing), next to the read
// they should not outweigh (issue 30, item 3), and the passes they replace.
// Prints every run and the median.
//
//   bench_preparation [MESH] [RUNS]   (default: ../shared/meshes/bunny-1M.ply next to the repo, 5 runs)
#include "bench_mesh.h"
#include "time_it.h"

#include "app/mesh_source.h"
#include "render/camera/camera.h"

#include "geometry/io/mesh_io.h"
#include "geometry/mesh/crease_candidates.h"
#include "geometry/mesh/crease_vote.h"
#include "geometry/mesh/creases.h"
#include "geometry/mesh/drawing_units.h"
#include "geometry/mesh/edge_bends.h"
#include "geometry/mesh/face_survey.h"
#include "geometry/mesh/orientation.h"
#include "geometry/mesh/position_bounds.h"
#include "geometry/parallel/parallel.h"
#include "geometry/view/default_view.h"

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
    const kappa::VertexFaces vf = kappa::build_vertex_faces(mesh);
    const kappa::ResolvedCreases resolved = kappa::resolve_creases(mesh, vf, -1);
    const float angle = resolved.angle;
    const kappa::CreaseVote vote = kappa::sampled_crease_vote(mesh, vf);
    const std::vector<uint32_t> candidates = kappa::crease_candidates(mesh, vf, kappa::kAutoCreaseAngle);
    std::printf("%s: %zu vertices, %zu faces, %u threads; auto crease angle %g (sampled vote: %s), %zu creases; "
                "%zu crease candidates at %g degrees\n",
                path.c_str(), mesh.vertex_count(), mesh.face_count(), kappa::thread_count(), angle,
                vote == kappa::CreaseVote::On ? "on" : vote == kappa::CreaseVote::Off ? "off" : "unclear",
                resolved.creases.size(), candidates.size(), kappa::kAutoCreaseAngle);

    time_it("read", runs, [&] { kappa::load_mesh(path); });
    time_it("drawing units", runs, [&] { kappa::drawing_units(mesh); });
    time_it("vertex faces (adjacency)", runs, [&] { kappa::build_vertex_faces(mesh); });
    time_it("sampled crease vote", runs, [&] { kappa::sampled_crease_vote(mesh, vf); });
    const glm::vec3 apex = kappa::position_bounds(mesh.positions).center();  // as the app gives it
    time_it("face pass: volumes", runs, [&] { kappa::survey_faces(mesh, vf, 0, apex); });
    time_it("face pass: + candidates", runs, [&] { kappa::survey_faces(mesh, vf, kappa::kAutoCreaseAngle, apex); });
    time_it("creases around them", runs,
            [&] { kappa::creases_around(mesh, vf, kappa::kAutoCreaseAngle, candidates); });
    time_it("  whole edge pass (before)", runs, [&] { kappa::measure_edge_bends(mesh, vf, kappa::kAutoCreaseAngle); });
    time_it("mesh copy", runs, [&] { kappa::Mesh copy = mesh; });
    auto rows_as_built = [&] {  // a copy of the rows with the room build_vertex_faces leaves
        kappa::VertexFaces rows = vf;
        rows.offsets.reserve(kappa::row_starts_room(mesh.vertex_count()));
        return rows;
    };
    time_it("copy + split (rows given)", runs, [&] {
        kappa::VertexFaces rows = rows_as_built();
        kappa::split_at_creases(mesh, resolved.creases, &rows);
    });
    time_it("  rows copy", runs, [&] { kappa::VertexFaces rows = vf; });
    {
        kappa::Mesh m;
        kappa::VertexFaces rows;
        kappa::SplitMesh split;
        time_it("split alone (rows given)", runs,
                [&] { split = kappa::split_at_creases(std::move(m), resolved.creases, &rows); }, 24, [&] {
                    split = {};
                    m.positions.reserve(kappa::positions_room(mesh.vertex_count()));  // as a reader leaves it
                    m.positions = mesh.positions, m.faces = mesh.faces, rows = rows_as_built();
                });
    }
    time_it("default view (rows given)", runs, [&] { kappa::default_view_as_read(mesh, std::nullopt, false, &vf); });
    time_it("  default view (before)", runs, [&] { kappa::default_view_as_read(mesh); });
    // What app/mesh_drawing.cpp does between the read and the fields (its "load" less the read): the
    // app's prepare_for_drawing (app/mesh_source.cpp), the split and the bounding sphere. The copies stand
    // for the mesh just read and its rows just built.
    time_it("copies + all of them", runs, [&] {
        kappa::Mesh m;
        m.positions.reserve(kappa::positions_room(mesh.vertex_count()));  // as a reader leaves it
        m.positions = mesh.positions, m.faces = mesh.faces;
        kappa::VertexFaces rows = rows_as_built();
        const kappa::app::DrawingPreparation prepared = kappa::app::prepare_for_drawing(m, rows, -1);  // auto
        const kappa::SplitMesh split = kappa::split_at_creases(std::move(m), prepared.creases.creases, &rows);
        kappa::render::bounding_sphere(split.mesh, prepared.box);
    });
    time_it("  copies alone", runs, [&] {
        kappa::Mesh m;
        m.positions.reserve(kappa::positions_room(mesh.vertex_count()));
        m.positions = mesh.positions, m.faces = mesh.faces;
        kappa::VertexFaces rows = rows_as_built();
    });
    return 0;
}
