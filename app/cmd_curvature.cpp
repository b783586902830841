// `kappa curvature MESH -o OUT.csv|OUT.ply`: computes normals, curvature and
// its derivative per vertex and writes them (columns: conventions.md).
#include "cli_options.h"
#include "commands.h"
#include "mesh_source.h"
#include "progress_bar.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/io/output_file.h"
#include "geometry/parallel/parallel.h"
#include "geometry/surface_analysis.h"
#include "geometry/curvature/vertex_flags.h"

#include <algorithm>
#include <optional>
#include <chrono>
#include <cstdio>
#include <string>

namespace kappa::app {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Range of a field over the vertices with no flag set; nullopt when every
// vertex is flagged (nothing could be estimated).
std::optional<std::pair<float, float>> reliable_range(const std::vector<float>& values,
                                                      const std::vector<uint8_t>& flags) {
    std::optional<std::pair<float, float>> range;
    for (size_t i = 0; i < values.size(); ++i) {
        if (flags[i]) continue;
        if (!range) range = std::make_pair(values[i], values[i]);
        range->first = std::min(range->first, values[i]);
        range->second = std::max(range->second, values[i]);
    }
    return range;
}

}  // namespace

int run_curvature(int argc, char** argv) {
    std::string mesh_path, out_path, format;
    SmoothingOptions smoothing;
    bool quiet = false;
    cli::Parser p("curvature", "[MESH] -o OUT.csv|OUT.ply [options]",
                  "Estimate per-vertex normals, principal curvatures and directions, and the derivative of "
                  "curvature C (Rusinkiewicz 2004), and write them as CSV or PLY.");
    p.positional("MESH", mesh_path, "mesh file (.ply .obj .off .stl .gltf .glb); default: the built-in model", false)
        .text("-o,--output", out_path, "output file: .csv, or .ply (binary unless --format ply-ascii)", "OUT")
        .choice("--format", format, {"csv", "ply", "ply-ascii"},
                "output format (default: from the output file's extension)")
        .smoothing(smoothing)
        .flag("-q,--quiet", quiet, "print nothing but errors")
        .threads()
        .epilog("CSV columns, one row per input vertex in input order:\n"
                "  x,y,z,nx,ny,nz,k1,k2,d1x,d1y,d1z,d2x,d2y,d2z,a,b,c,d\n"
                "k1 >= k2 (signed, convex positive), d1 x d2 = n, (a,b,c,d) = (C111,C112,C122,C222) in the\n"
                "(d1,d2) frame. The PLY output carries the same values as vertex properties, plus 'flags'\n"
                "(1 isolated, 2 degenerate, 4 boundary, 8 non-manifold, 16 estimator fallback).\n"
                "--estimator jet is the most accurate (a noise-adaptive osculating jet); the others are the\n"
                "paper's comparison methods (docs/estimators-and-accuracy.md).\n"
                "Smoothing is off by default (the raw estimate, reproducible). For scans and other noisy\n"
                "meshes use --smooth auto: it estimates the noise and chooses the widths, printed in the\n"
                "summary and written in the PLY header (docs/detail-and-noise.md).\n"
                "Example: kappa curvature scan.ply -o scan.ply --smooth auto");
    if (auto status = p.parse(argc, argv)) return *status;
    if (out_path.empty()) {
        std::fprintf(stderr, "kappa curvature: missing -o OUT.csv|OUT.ply (see 'kappa curvature --help')\n");
        return 2;
    }
    if (format.empty()) {
        const std::string ext = io::lower_extension(out_path);
        if (ext == "csv" || ext == "ply") {
            format = ext;
        } else {
            std::fprintf(stderr, "kappa curvature: cannot tell the format of '%s': use .csv or .ply, or --format\n",
                         out_path.c_str());
            return 2;
        }
    }
    if (auto problem = io::output_problem(out_path)) {  // before the mesh is read and curvature computed
        std::fprintf(stderr, "kappa curvature: cannot write %s: %s\n", out_path.c_str(), problem->c_str());
        return 1;
    }

    try {
        const auto t_load = std::chrono::steady_clock::now();
        const Mesh mesh = load_mesh_or_default(mesh_path);
        const double load_s = seconds_since(t_load);

        ProgressBar bar(!quiet && mesh.face_count() >= 200000);
        StageTimes times;
        const SurfaceFields fields =
            compute_surface_fields(mesh, smoothing, &times, [&](float f, const char* stage) { bar.update(f, stage); });
        bar.finish();

        const auto t_write = std::chrono::steady_clock::now();
        if (format == "csv")
            write_csv(out_path, mesh, fields);
        else
            write_ply(out_path, mesh, fields, format == "ply");
        const double write_s = seconds_since(t_write);
        if (quiet) return 0;

        size_t boundary = 0, flagged = 0;
        for (uint8_t f : fields.flags) {
            boundary += (f & kFlagBoundary) != 0;
            flagged += f != 0;
        }
        const auto k1 = reliable_range(fields.k1, fields.flags), k2 = reliable_range(fields.k2, fields.flags);
        std::printf("%s: %zu vertices, %zu faces\n", mesh_display_name(mesh_path).c_str(),
                    mesh.vertex_count(), mesh.face_count());
        std::printf("  boundary vertices %zu, flagged (unreliable) vertices %zu\n", boundary, flagged);
        if (k1 && k2)
            std::printf("  k1 in [%.6g, %.6g], k2 in [%.6g, %.6g] (unflagged vertices)\n", k1->first, k1->second,
                        k2->first, k2->second);
        else
            std::printf("  every vertex is flagged: no curvature could be estimated (all written as 0)\n");
        std::printf("  feature size %.6g\n", feature_size(mesh, fields));
        if (fields.smoothing.automatic)
            std::printf("  noise level %.6g (%.4g median edges of %.6g), estimated from %zu vertices\n",
                        fields.noise.sigma, fields.noise.relative, fields.noise.median_edge, fields.noise.samples);
        if (fields.smoothing.estimator != Estimator::rusinkiewicz)
            std::printf("  estimator %s\n", estimator_name(fields.smoothing.estimator).c_str());
        std::printf("  smoothing widths%s: normals %.6g, curvature %.6g, dcurv %.6g\n",
                    fields.smoothing.automatic ? " (auto)" : "", fields.smoothing.normals, fields.smoothing.curvature,
                    fields.smoothing.dcurv);
        std::printf("  worker threads: %u\n", kappa::thread_count());
        std::printf("  time: load %.3f s, adjacency %.3f s, normals %.3f s, areas %.3f s, curvature %.3f s, "
                    "dcurv %.3f s, smoothing %.3f s, write %.3f s\n",
                    load_s, times.adjacency, times.normals, times.areas, times.curvature, times.dcurv,
                    times.smoothing, write_s);
        std::printf("  wrote %s\n", out_path.c_str());
        return 0;
    } catch (const MeshLoadError& e) {
        return cli::fail(e.what());
    } catch (const MeshWriteError& e) {
        return cli::fail(e.what());
    }
}

}  // namespace kappa::app
