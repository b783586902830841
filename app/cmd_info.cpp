// `kappa info [MESH]`: counts, bounds, edge lengths, topology and feature
// size of a mesh, one "name: value" line each (easy to read and to grep).
#include "cli_options.h"
#include "commands.h"
#include "mesh_source.h"
#include "progress_bar.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/mesh/mesh_stats.h"
#include "geometry/surface_analysis.h"
#include "geometry/view/default_view.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace kappa::app {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void print_line(const char* name, const std::string& value) {
    std::printf("%-22s%s\n", (std::string(name) + ":").c_str(), value.c_str());
}

std::string format(const char* fmt, double a, double b = 0, double c = 0, double d = 0) {
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, a, b, c, d);
    return buf;
}

void print_stats(const MeshStats& s) {
    const Topology& t = s.topology;
    print_line("vertices", std::to_string(s.vertices));
    print_line("faces", std::to_string(s.faces));
    print_line("edges", std::to_string(t.edges));
    const glm::vec3 lo = s.bounds.min, hi = s.bounds.max, size = s.bounds.size();
    print_line("bounding box min", format("%.6g %.6g %.6g", lo.x, lo.y, lo.z));
    print_line("bounding box max", format("%.6g %.6g %.6g", hi.x, hi.y, hi.z));
    print_line("bounding box size", format("%.6g %.6g %.6g", size.x, size.y, size.z));
    const EdgeLengthStats& e = s.edge_lengths;
    print_line("edge length", format("min %.6g  mean %.6g  median %.6g  max %.6g", e.min, e.mean, e.median, e.max));
    print_line("components", std::to_string(t.components));
    print_line("boundary edges", std::to_string(t.boundary_edges));
    print_line("boundary loops", std::to_string(t.boundary_loops));
    print_line("non-manifold edges", std::to_string(t.nonmanifold_edges));
    print_line("degenerate faces", std::to_string(s.degenerate_faces));
    print_line("isolated vertices", std::to_string(t.isolated_vertices));
    print_line("euler characteristic", std::to_string(t.euler_characteristic));
}

}  // namespace

int run_info(int argc, char** argv) {
    std::string mesh_path;
    bool no_curvature = false, timings = false;
    cli::Parser p("info", "[MESH] [options]",
                  "Print statistics of a mesh: counts, bounding box, edge lengths, connected\n"
                  "components, boundary edges and loops, non-manifold edges, degenerate faces,\n"
                  "isolated vertices, Euler characteristic (V - E + F), the default view of\n"
                  "kappa render (unit vectors from the model's centre towards the eye and up)\n"
                  "and feature size.");
    p.positional("MESH", mesh_path, "mesh file (.ply .obj .off .stl .gltf .glb); default: the built-in model", false)
        .flag("--no-curvature", no_curvature, "skip the curvature estimate (no feature size; faster)")
        .flag("--timings", timings, "print the time of each step on stderr")
        .threads()
        .epilog(
            "Definitions: a boundary edge has one face, a non-manifold edge three or more;\n"
            "a boundary loop is a closed chain of boundary edges (holes touching at one\n"
            "vertex count separately); isolated vertices (no face) are not components.\n"
            "The feature size fs is the median smaller radius of curvature over reliable\n"
            "vertices, clamped to [median edge length, bounding-sphere radius];\n"
            "thresholds on suggestive contours scale by 1/fs^2 (docs/curvature.md).");
    if (auto status = p.parse(argc, argv)) return *status;

    auto start = std::chrono::steady_clock::now();
    // load_mesh throws MeshLoadError("PATH: problem"); main prints it, exit 1.
    const Mesh mesh = load_mesh_or_default(mesh_path);
    const double load_s = seconds_since(start);

    start = std::chrono::steady_clock::now();
    const MeshStats stats = compute_mesh_stats(mesh);
    const double stats_s = seconds_since(start);

    print_line("mesh", mesh_display_name(mesh_path));
    print_stats(stats);
    // What kappa render draws without --view/--eye/--up (docs/rendering.md,
    // 'The default view'): --eye EYE --up UP from the centre gives it again.
    const DefaultView view = default_view(mesh, file_up_axis(mesh_path));
    auto c = [](float v) { return std::fabs(v) < 5e-5f ? 0.0 : double(v); };  // no "-0.0000"
    print_line("default view", format("eye %.4f,%.4f,%.4f", c(view.eye.x), c(view.eye.y), c(view.eye.z)) +
                                   format(" up %.4f,%.4f,%.4f", c(view.up.x), c(view.up.y), c(view.up.z)));

    double curvature_s = 0;
    if (!no_curvature) {
        start = std::chrono::steady_clock::now();
        ProgressBar bar(true);
        const SurfaceFields fields =
            compute_surface_fields(mesh, {}, nullptr, [&](float f, const char* stage) { bar.update(f, stage); });
        bar.finish();
        print_line("feature size", format("%.6g", feature_size(mesh, fields)));
        curvature_s = seconds_since(start);
    }
    std::fflush(stdout);
    if (timings)
        std::fprintf(stderr, "timings: load %.3f s, statistics %.3f s, curvature %.3f s\n", load_s, stats_s,
                     curvature_s);
    return 0;
}

}  // namespace kappa::app
