#include "tensor_averaging.h"

#include "geometry/parallel/parallel.h"
#include "tensor_frames.h"
#include "vertex_flags.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <cmath>

namespace kappa {

namespace {

// The face other than `f` at vertex `at` that traverses the edge to -> at
// (the neighbour of f across edge at -> to in a consistently oriented mesh);
// -1 when there is none.
int64_t face_across(const Mesh& mesh, const VertexFaces& vf, uint32_t at, uint32_t to, uint32_t f) {
    for (uint32_t k = vf.begin(at); k < vf.end(at); ++k) {
        const uint32_t c = vf.corners[k], g = c / 3;
        if (g != f && mesh.faces[g][(c + 2) % 3] == to) return g;
    }
    return -1;
}

// beta(e) |e| e e^T for the edge a -> b of face f, when it has a face across.
void add_edge(const EstimatorInput& in, uint32_t a, uint32_t b, uint32_t f, double weight, glm::dmat3& T) {
    const int64_t g = face_across(in.mesh, in.vf, a, b, f);
    if (g < 0) return;
    const glm::dvec3 nf(in.faces.area_normal(f)), ng(in.faces.area_normal(size_t(g)));
    const double lf = glm::length(nf), lg = glm::length(ng);
    if (!(lf > 0) || !(lg > 0)) return;
    const glm::dvec3 d = glm::dvec3(in.mesh.positions[b]) - glm::dvec3(in.mesh.positions[a]);
    const double len = glm::length(d);
    if (!(len > 0)) return;
    const glm::dvec3 e = d / len;
    const double beta = std::atan2(glm::dot(glm::cross(nf, ng), e) / (lf * lg), glm::dot(nf, ng) / (lf * lg));
    const double s = weight * beta * len;
    for (int c = 0; c < 3; ++c) T[c] += s * e[c] * e;
}

}  // namespace

CurvatureEstimate estimate_tensor_averaging(const EstimatorInput& in) {
    const size_t nv = in.mesh.vertex_count();
    CurvatureEstimate out = empty_estimate(nv, false);
    parallel_for(nv, [&](size_t v) {
        glm::dmat3 T(0.0);
        double area = 0;
        for (uint32_t k = in.vf.begin(v); k < in.vf.end(v); ++k) {
            const uint32_t c = in.vf.corners[k], f = c / 3;
            const Face& face = in.mesh.faces[f];
            const uint32_t a = face[(c + 1) % 3], b = face[(c + 2) % 3];
            area += 0.5 * glm::length(glm::dvec3(in.faces.area_normal(f)));
            add_edge(in, uint32_t(v), a, f, 1.0, T);  // spoke v -> a; v <- b is b's face's spoke
            add_edge(in, a, b, f, 0.5, T);            // rim edge, on the border of B
        }
        if (!(area > 0)) {
            out.flags[v] = kFlagFallback;
            return;
        }
        const VertexFrame f = vertex_frame(in, v);
        const glm::dvec3 &u = f.u, &w = f.w;
        const double tuu = glm::dot(u, T * u) / area, tuv = glm::dot(u, T * w) / area, tvv = glm::dot(w, T * w) / area;
        if (!std::isfinite(tuu) || !std::isfinite(tuv) || !std::isfinite(tvv)) {
            out.flags[v] = kFlagFallback;
            return;
        }
        out.tensors.tensor[v] = {float(tvv), float(-tuv), float(tuu)};
    });
    return out;
}

}  // namespace kappa
