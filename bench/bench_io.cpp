// Mesh I/O timings: loads each shared mesh several times (file read + parse;
// the first run warms the page cache) and writes the CSV and PLY outputs of
// the 1M-triangle bunny. Prints every run and the median.
//
//   bench_io [MESH_DIR] [RUNS]     (default: ../shared/meshes next to the repo, 11 runs)
#include "median.h"

#include "geometry/io/mesh_io.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

using Clock = std::chrono::steady_clock;

using kappa::bench::median;

namespace {

// Runs `body` once as a warm-up (printed as "first": for the first mesh of
// the process this is what a fresh `kappa` run pays, page faults included),
// then `runs` timed times; prints each run and the median.
void time_it(const std::string& label, int runs, const std::function<void()>& body) {
    std::printf("%-30s", label.c_str());
    auto t0 = Clock::now();
    body();
    std::printf(" first %.1f |", std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    std::vector<double> ms;
    for (int r = 0; r < runs; ++r) {
        t0 = Clock::now();
        body();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        std::printf(" %.1f", ms.back());
    }
    std::printf(" | median %.2f ms\n", median(ms));
    std::fflush(stdout);
}

// Plausible per-vertex fields (the values do not matter for timing).
kappa::SurfaceFields fake_fields(const kappa::Mesh& mesh) {
    kappa::SurfaceFields f;
    size_t n = mesh.vertex_count();
    f.normals.resize(n);
    f.d1.resize(n);
    f.d2.resize(n);
    f.k1.resize(n);
    f.k2.resize(n);
    f.dcurv.resize(n);
    f.flags.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        glm::vec3 p = mesh.positions[i];
        f.normals[i] = p * 3.1f;
        f.d1[i] = {p.y, -p.x, 0.3f};
        f.d2[i] = {p.z * 1.7f, 0.25f, -p.x};
        f.k1[i] = 1.0f / (0.01f + p.x * p.x);
        f.k2[i] = -p.y * 123.456f;
        f.dcurv[i] = {p.x * 1e3f, p.y * 1e-3f, p.z, 1.0f / 3.0f};
    }
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    std::filesystem::path source_dir = std::filesystem::path(__FILE__).parent_path().parent_path();
    std::string dir = argc > 1 ? argv[1] : (source_dir / ".." / "shared" / "meshes").string();
    int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 11;
    std::printf("mesh directory: %s, %d runs each (ms)\n", dir.c_str(), runs);

    try {
        for (const char* name : {"bunny-1M.ply", "dragon-50k.ply", "bunny.ply", "fandisk.obj", "spot.obj"}) {
            std::string path = dir + "/" + name;
            kappa::Mesh mesh;
            time_it(std::string("load ") + name, runs, [&] { mesh = kappa::load_mesh(path); });
            std::printf("%30s %zu vertices, %zu faces\n", "", mesh.vertex_count(), mesh.face_count());
        }

        kappa::Mesh big = kappa::load_mesh(dir + "/bunny-1M.ply");
        kappa::SurfaceFields fields = fake_fields(big);
        std::string out = (std::filesystem::temp_directory_path() / "kappa-bench-io").string();
        time_it("write_csv bunny-1M", runs, [&] { kappa::write_csv(out + ".csv", big, fields); });
        time_it("write_ply binary bunny-1M", runs,
                [&] { kappa::write_ply(out + ".ply", big, fields, true); });
        time_it("load written binary PLY (19 props)", runs, [&] { big = kappa::load_mesh(out + ".ply"); });
        int ascii_runs = std::max(1, runs / 3);
        time_it("write_ply ascii bunny-1M", ascii_runs,
                [&] { kappa::write_ply(out + ".ply", big, fields, false); });
        time_it("load written ascii PLY (19 props)", ascii_runs,
                [&] { big = kappa::load_mesh(out + ".ply"); });
        std::filesystem::remove(out + ".csv");
        std::filesystem::remove(out + ".ply");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_io: %s\n", e.what());
        return 1;
    }
    return 0;
}
