#include "points_normals_fit.h"

#include "graph_geometry.h"
#include "normal_equations.h"
#include "rings.h"

#include "geometry/parallel/parallel.h"
#include "tensor_frames.h"
#include "vertex_flags.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

CurvatureEstimate estimate_points_normals_fit(const EstimatorInput& in) {
    const size_t nv = in.mesh.vertex_count();
    const VertexAdjacency adj = build_vertex_adjacency(in.mesh, in.vf);
    CurvatureEstimate out = empty_estimate(nv, true);
    parallel_for(nv, [&](size_t v) {
        const auto [p, u, w, n] = vertex_frame(in, v);
        double scale = 0;
        for (uint32_t k = adj.begin(v); k < adj.end(v); ++k)
            scale = std::max(scale, glm::length(glm::dvec3(in.mesh.positions[adj.neighbours[k]]) - p));
        if (!(scale > 0) || !std::isfinite(scale)) {
            out.flags[v] = kFlagFallback;
            return;
        }
        // Unknowns (A, B, C, D, E, F, G), quadratic ones first.
        NormalEquations<7> eq;
        for (uint32_t k = adj.begin(v); k < adj.end(v); ++k) {
            const uint32_t q = adj.neighbours[k];
            const glm::dvec3 d = (glm::dvec3(in.mesh.positions[q]) - p) / scale;
            const double x = glm::dot(d, u), y = glm::dot(d, w), z = glm::dot(d, n);
            const double z_row[7] = {x * x / 2, x * y, y * y / 2, x * x * x, x * x * y, x * y * y, y * y * y};
            eq.add(z_row, z);
            const glm::dvec3 m(in.normals[q]);
            const double a = glm::dot(m, u), b = glm::dot(m, w), c = glm::dot(m, n);
            if (!(c > 1e-3)) continue;  // a normal turned by ~90 degrees says nothing about the slope here
            const double zx_row[7] = {x, y, 0, 3 * x * x, 2 * x * y, y * y, 0};
            const double zy_row[7] = {0, x, y, 0, x * x, 2 * x * y, 3 * y * y};
            eq.add(zx_row, -a / c);
            eq.add(zy_row, -b / c);
        }
        double s[7];
        int used = 7;
        if (!eq.solve(7, s, 1e-9)) {
            used = 3;
            if (!eq.solve(3, s, 1e-9)) {
                out.flags[v] = kFlagFallback;
                return;
            }
        }
        HeightDerivatives h;  // model units: f_ij scale by 1/scale, f_ijk by 1/scale^2
        h.fxx = s[0] / scale;
        h.fxy = s[1] / scale;
        h.fyy = s[2] / scale;
        const double inv2 = 1.0 / (scale * scale);
        h.fxxx = 6 * s[3] * inv2;
        h.fxxy = 2 * s[4] * inv2;
        h.fxyy = 2 * s[5] * inv2;
        h.fyyy = 6 * s[6] * inv2;
        double II[3], C[4];
        graph_curvature(h, glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), II, C);  // (u, w) is the output frame
        out.tensors.tensor[v] = {float(II[0]), float(II[1]), float(II[2])};
        out.dcurv_uv[v] = glm::vec4(float(C[0]), float(C[1]), float(C[2]), float(C[3]));
        if (used < 7) out.flags[v] = kFlagFallback;
    });
    return out;
}

}  // namespace kappa
