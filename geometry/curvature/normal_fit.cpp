#include "normal_fit.h"

#include "normal_equations.h"
#include "rings.h"

#include "geometry/parallel/parallel.h"
#include "tensor_frames.h"
#include "vertex_flags.h"

#include <glm/geometric.hpp>

namespace kappa {

CurvatureEstimate estimate_normal_fit(const EstimatorInput& in) {
    const size_t nv = in.mesh.vertex_count();
    const VertexAdjacency adj = build_vertex_adjacency(in.mesh, in.vf);
    CurvatureEstimate out = empty_estimate(nv, false);
    parallel_for(nv, [&](size_t v) {
        const auto [p, u, w, n] = vertex_frame(in, v);
        NormalEquations<3> eq;
        for (uint32_t k = adj.begin(v); k < adj.end(v); ++k) {
            const glm::dvec3 d = glm::dvec3(in.mesh.positions[adj.neighbours[k]]) - p;
            const double len2 = glm::dot(d, d);
            const double su = glm::dot(d, u), sv = glm::dot(d, w), st2 = su * su + sv * sv;
            if (!(len2 > 0) || !(st2 > 0)) continue;
            const double kn = -2.0 * glm::dot(n, d) / len2;  // eq. 3
            const double row[3] = {su * su / st2, 2 * su * sv / st2, sv * sv / st2};
            eq.add(row, kn);  // eq. 1: II(s, s) for the unit s
        }
        double x[3];
        if (!eq.solve(3, x, 1e-9)) {
            out.flags[v] = kFlagFallback;
            return;
        }
        out.tensors.tensor[v] = {float(x[0]), float(x[1]), float(x[2])};
    });
    return out;
}

}  // namespace kappa
