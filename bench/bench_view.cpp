// bench_view: the viewer's speed, measured on the real `kappa view` in a
// window (under xvfb-run when there is no DISPLAY), medians over runs:
//   1. opening bunny-1M.ply to the first drawn frame, and the part of it the
//      issue budgets (load + curvature + upload, 1.5 s);
//   2. frame time while orbiting the built-in model at 1280x800;
//   3. frame time while orbiting bunny-1M.ply as its curvature is
//      recomputed in the background (a smoothing width changed).
// Usage: bench_view [RUNS=5] [MESH_DIR=<source>/../shared/meshes]
#include "median.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

using kappa::bench::median;

namespace {

std::string kappa_exe(const char* argv0) {
    std::string self = argv0;
    const auto slash = self.find_last_of('/');
    return (slash == std::string::npos ? std::string(".") : self.substr(0, slash)) + "/kappa";
}

std::string run(const std::string& command) {
    std::string out;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return out;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
    pclose(pipe);
    return out;
}

// The number after `key` in `text`, or -1.
double number_after(const std::string& text, const std::string& key) {
    const auto at = text.find(key);
    return at == std::string::npos ? -1 : std::atof(text.c_str() + at + key.size());
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    const std::string meshes = argc > 2 ? argv[2] : std::string(KAPPA_SOURCE_DIR) + "/../shared/meshes";
    const char* display = std::getenv("DISPLAY");
    const std::string prefix = display && *display ? "" : "xvfb-run -a -s '-screen 0 1280x800x24 -noreset' ";
    const std::string view = prefix + kappa_exe(argv[0]) + " view ";
    const std::string bunny = meshes + "/bunny-1M.ply";

    const std::string orbit_script = "/tmp/bench_view_orbit.txt", recompute_script = "/tmp/bench_view_recompute.txt";
    std::ofstream(orbit_script) << "frames 2\ndrag 500 400 900 300 left 40\nframes 1\n";
    std::ofstream(recompute_script) << "frames 1\nset smooth-curvature 0.0005\ndrag 500 400 900 300 left 20\n"
                                       "wait-compute\nframes 1\n";

    std::vector<double> first, stages, orbit, recompute;
    for (int i = 0; i < runs; ++i) {
        const std::string a = run(view + bunny + " --size 1024x768 --frames 1");
        first.push_back(number_after(a, "first frame at "));
        stages.push_back(number_after(a, "(load ") + number_after(a, "curvature ") + number_after(a, "upload "));
        orbit.push_back(number_after(run(view + "--size 1280x800 --script " + orbit_script), "while dragging, median "));
        recompute.push_back(
            number_after(run(view + bunny + " --size 1024x768 --script " + recompute_script), "while dragging, median "));
        std::printf("run %d: bunny-1M first frame %.3f s (load+curvature+upload %.3f s); orbit default %.1f ms; "
                    "orbit bunny-1M while recomputing %.1f ms\n",
                    i + 1, first.back(), stages.back(), orbit.back(), recompute.back());
        std::fflush(stdout);
    }
    std::printf("median of %d runs:\n", runs);
    std::printf("  bunny-1M.ply to the first drawn frame (1024x768)  %.3f s\n", median(first));
    std::printf("    of which load + curvature + upload            %.3f s\n", median(stages));
    std::printf("  orbiting the built-in model (1280x800)           %.1f ms/frame\n", median(orbit));
    std::printf("  orbiting bunny-1M while curvature recomputes     %.1f ms/frame\n", median(recompute));
    return 0;
}
