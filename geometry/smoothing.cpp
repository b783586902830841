#include "smoothing.h"

#include "parallel.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace kappa {

namespace {

// Calls visit(j, w) for every vertex j in the Gaussian neighbourhood of
// every vertex i (see the header), i itself included; `begin(i)` starts a
// vertex and `finish(i, sum_w)` ends it. Each thread keeps its own visit
// stamps; each vertex is handled by one thread, in a fixed order.
template <typename Begin, typename Visit, typename Finish>
void for_each_neighbourhood(const SmoothingContext& ctx, float sigma, Begin begin, Visit visit, Finish finish) {
    const size_t nv = ctx.mesh.vertex_count();
    const float cutoff2 = 9.0f * sigma * sigma;
    const float inv2s2 = 1.0f / (2.0f * sigma * sigma);
    parallel_for_ranges(nv, [&](size_t first, size_t last) {
        std::vector<uint32_t> stamp(nv, UINT32_MAX);
        std::vector<uint32_t> stack;
        for (size_t i = first; i < last; ++i) {
            begin(i);
            const glm::vec3 p0 = ctx.mesh.positions[i];
            const glm::vec3 n0 = ctx.normals[i];
            double sum_w = 0;
            stack.assign(1, uint32_t(i));
            stamp[i] = uint32_t(i);
            while (!stack.empty()) {
                const uint32_t j = stack.back();
                stack.pop_back();
                const glm::vec3 d = ctx.mesh.positions[j] - p0;
                const float d2 = glm::dot(d, d);
                const float facing = glm::dot(n0, ctx.normals[j]);
                if (d2 >= cutoff2 || (facing <= 0.0f && j != i)) continue;
                const float w = std::exp(-d2 * inv2s2) * ctx.point_areas[j] * (j == i ? 1.0f : facing);
                if (w > 0) {
                    visit(i, j, w);
                    sum_w += w;
                }
                for (uint32_t k = ctx.vf.begin(j); k < ctx.vf.end(j); ++k) {
                    const uint32_t c = ctx.vf.corners[k];
                    const Face& f = ctx.mesh.faces[c / 3];
                    for (int s = 1; s <= 2; ++s) {
                        const uint32_t nb = f[(c % 3 + s) % 3];
                        if (stamp[nb] != i) {
                            stamp[nb] = uint32_t(i);
                            stack.push_back(nb);
                        }
                    }
                }
            }
            finish(i, sum_w);
        }
    }, 1024);
}

}  // namespace

void smooth_normals(const SmoothingContext& ctx, float sigma, std::vector<glm::vec3>& out) {
    if (!(sigma > 0)) return;
    std::vector<glm::vec3> result(ctx.normals.size());
    // Accumulators are per vertex i, written only by the thread that owns i.
    std::vector<glm::dvec3> acc(ctx.normals.size());
    for_each_neighbourhood(
        ctx, sigma, [&](size_t i) { acc[i] = glm::dvec3(0.0); },
        [&](size_t i, uint32_t j, float w) { acc[i] += double(w) * glm::dvec3(ctx.normals[j]); },
        [&](size_t i, double) {
            const double len = glm::length(acc[i]);
            result[i] = len > 0 ? glm::vec3(acc[i] / len) : ctx.normals[i];
        });
    out = std::move(result);
}

void smooth_curvature_tensors(const SmoothingContext& ctx, float sigma, VertexTensors& tensors) {
    if (!(sigma > 0)) return;
    std::vector<glm::dvec3> acc(tensors.tensor.size());
    std::vector<Tensor2> result(tensors.tensor.size());
    for_each_neighbourhood(
        ctx, sigma, [&](size_t i) { acc[i] = glm::dvec3(0.0); },
        [&](size_t i, uint32_t j, float w) {
            glm::vec3 ui, vi, uj, vj;
            tangent_frame(ctx.normals[i], ui, vi);
            tangent_frame(ctx.normals[j], uj, vj);
            const Tensor2 r = project_tensor(uj, vj, tensors.tensor[j], ui, vi);
            acc[i] += double(w) * glm::dvec3(r.ku, r.kuv, r.kv);
        },
        [&](size_t i, double sum_w) {
            result[i] = sum_w > 0 ? Tensor2{float(acc[i].x / sum_w), float(acc[i].y / sum_w), float(acc[i].z / sum_w)}
                                  : tensors.tensor[i];
        });
    tensors.tensor = std::move(result);
}

void smooth_dcurv(const SmoothingContext& ctx, float sigma, const std::vector<glm::vec3>& d1,
                  const std::vector<glm::vec3>& d2, std::vector<glm::vec4>& dcurv) {
    if (!(sigma > 0)) return;
    std::vector<glm::dvec4> acc(dcurv.size());
    std::vector<glm::vec4> result(dcurv.size());
    for_each_neighbourhood(
        ctx, sigma, [&](size_t i) { acc[i] = glm::dvec4(0.0); },
        [&](size_t i, uint32_t j, float w) {
            acc[i] += double(w) * glm::dvec4(project_dcurv(d1[j], d2[j], dcurv[j], d1[i], d2[i]));
        },
        [&](size_t i, double sum_w) { result[i] = sum_w > 0 ? glm::vec4(acc[i] / sum_w) : dcurv[i]; });
    dcurv = std::move(result);
}

}  // namespace kappa
