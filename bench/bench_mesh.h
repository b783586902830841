// The mesh argument of the estimator benchmarks (bench_estimators,
// bench_cgal_jet): a mesh file, or `torus`, the accuracy lab's clean
// irregular torus (R 1, r 0.4, 200 x 100 = 20k vertices, jitter 0.3), the
// size of issue 10's CGAL figure.
#pragma once

#include "tests/analytic_curvature.h"

#include "geometry/io/mesh_io.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace kappa::bench {

// A file that cannot be read ends the benchmark with one line naming it, not an uncaught exception.
inline Mesh load_or_exit(const std::string& path) {
    try {
        return load_mesh(path);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        std::exit(1);
    }
}

inline Mesh estimator_bench_mesh(const std::string& path) {
    return path == "torus" ? test::analytic_torus(1, 0.4, 200, 100, 0.3, 101).mesh : load_or_exit(path);
}

}  // namespace kappa::bench
