// The mesh argument of the estimator benchmarks (bench_estimators,
// bench_cgal_jet): a mesh file, or `torus`, the accuracy lab's clean
// irregular torus (R 1, r 0.4, 200 x 100 = 20k vertices, jitter 0.3), the
// size of issue 10's CGAL figure.
#pragma once

#include "tests/analytic_curvature.h"

#include "geometry/io/mesh_io.h"

#include <string>

namespace kappa::bench {

inline Mesh estimator_bench_mesh(const std::string& path) {
    return path == "torus" ? test::analytic_torus(1, 0.4, 200, 100, 0.3, 101).mesh : load_mesh(path);
}

}  // namespace kappa::bench
