#include "smoothing.h"

#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

// Vertex -> its distinct neighbours through faces, in increasing order (CSR).
// Walking these instead of the incident faces' corners halves the visits of
// the flood fill below and drops an indirection.
struct VertexNeighbours {
    std::vector<uint32_t> offsets, list;
};

VertexNeighbours build_neighbours(const Mesh& mesh, const VertexFaces& vf) {
    const size_t nv = mesh.vertex_count();
    VertexNeighbours out;
    out.offsets.assign(nv + 1, 0);
    auto gather = [&](size_t v, std::vector<uint32_t>& buf) {
        buf.clear();
        for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
            const uint32_t c = vf.corners[k];
            const Face& f = mesh.faces[c / 3];
            for (int s = 1; s <= 2; ++s) {
                const uint32_t nb = f[(c % 3 + s) % 3];
                if (nb != v) buf.push_back(nb);
            }
        }
        std::sort(buf.begin(), buf.end());
        buf.erase(std::unique(buf.begin(), buf.end()), buf.end());
    };
    parallel_for_ranges(nv, [&](size_t first, size_t last) {
        std::vector<uint32_t> buf;
        for (size_t v = first; v < last; ++v) {
            gather(v, buf);
            out.offsets[v + 1] = uint32_t(buf.size());
        }
    });
    for (size_t v = 0; v < nv; ++v) out.offsets[v + 1] += out.offsets[v];
    out.list.resize(out.offsets[nv]);
    parallel_for_ranges(nv, [&](size_t first, size_t last) {
        std::vector<uint32_t> buf;
        for (size_t v = first; v < last; ++v) {
            gather(v, buf);
            std::copy(buf.begin(), buf.end(), out.list.begin() + out.offsets[v]);
        }
    });
    return out;
}

struct Neighbour {
    uint32_t j;
    float w;
};

// Calls finish(i, first, last, sum_w) for every vertex i with its Gaussian
// neighbourhood [first, last) (see the header): the vertices j, i itself
// first, with their weights w > 0, and the sum of those weights. A vertex is tested once, when the flood fill first
// reaches it, and expanded only if it passes. Each thread keeps its own
// visit stamps and buffers; each vertex is handled by one thread, in a fixed
// order, so the sums do not depend on the thread count.
template <typename Finish>
void for_each_neighbourhood(const SmoothingContext& ctx, float sigma, Finish finish) {
    const size_t nv = ctx.mesh.vertex_count();
    const VertexNeighbours nbrs = build_neighbours(ctx.mesh, ctx.vf);
    const float cutoff2 = 9.0f * sigma * sigma;
    const float inv2s2 = 1.0f / (2.0f * sigma * sigma);
    const glm::vec3* pos = ctx.mesh.positions.data();
    const glm::vec3* nrm = ctx.normals.data();
    const float* area = ctx.point_areas.data();
    parallel_for_ranges(nv, [&](size_t first, size_t last) {
        std::vector<uint32_t> stamp(nv, UINT32_MAX);
        std::vector<uint32_t> stack;
        std::vector<Neighbour> hood;
        for (size_t i = first; i < last; ++i) {
            const glm::vec3 p0 = pos[i];
            const glm::vec3 n0 = nrm[i];
            size_t count = 0;
            double sum_w = 0;
            stamp[i] = uint32_t(i);
            stack.assign(1, uint32_t(i));
            while (!stack.empty()) {
                const uint32_t j = stack.back();
                stack.pop_back();
                const glm::vec3 d = pos[j] - p0;
                const float d2 = glm::dot(d, d);
                const float w = std::exp(-d2 * inv2s2) * area[j] * (j == i ? 1.0f : glm::dot(n0, nrm[j]));
                if (w > 0) {
                    if (count == hood.size()) hood.resize(2 * count + 64);
                    hood[count++] = {j, w};
                    sum_w += w;
                }
                for (uint32_t k = nbrs.offsets[j]; k < nbrs.offsets[j + 1]; ++k) {
                    const uint32_t nb = nbrs.list[k];
                    if (stamp[nb] == uint32_t(i)) continue;
                    stamp[nb] = uint32_t(i);
                    const glm::vec3 e = pos[nb] - p0;
                    if (glm::dot(e, e) < cutoff2 && glm::dot(n0, nrm[nb]) > 0.0f) stack.push_back(nb);
                }
            }
            finish(i, hood.data(), hood.data() + count, sum_w);
        }
    }, 1024);
}

}  // namespace

void smooth_normals(const SmoothingContext& ctx, float sigma, std::vector<glm::vec3>& out) {
    if (!(sigma > 0)) return;
    std::vector<glm::vec3> result(ctx.normals.size());
    for_each_neighbourhood(ctx, sigma, [&](size_t i, const Neighbour* first, const Neighbour* last, double) {
        glm::dvec3 acc(0.0);
        for (const Neighbour* h = first; h != last; ++h) acc += double(h->w) * glm::dvec3(ctx.normals[h->j]);
        const double len = glm::length(acc);
        result[i] = len > 0 ? glm::vec3(acc / len) : ctx.normals[i];
    });
    out = std::move(result);
}

void smooth_curvature_tensors(const SmoothingContext& ctx, float sigma, VertexTensors& tensors) {
    if (!(sigma > 0)) return;
    // Each vertex's tangent frame once (tangent_frame depends on the normal only).
    std::vector<glm::vec3> fu(ctx.normals.size()), fv(ctx.normals.size());
    parallel_for(ctx.normals.size(), [&](size_t i) { tangent_frame(ctx.normals[i], fu[i], fv[i]); });
    std::vector<Tensor2> result(tensors.tensor.size());
    for_each_neighbourhood(ctx, sigma, [&](size_t i, const Neighbour* first, const Neighbour* last, double sum_w) {
        glm::dvec3 acc(0.0);
        for (const Neighbour* h = first; h != last; ++h) {
            const Tensor2 r = project_tensor(fu[h->j], fv[h->j], tensors.tensor[h->j], fu[i], fv[i]);
            acc += double(h->w) * glm::dvec3(r.ku, r.kuv, r.kv);
        }
        result[i] = sum_w > 0 ? Tensor2{float(acc.x / sum_w), float(acc.y / sum_w), float(acc.z / sum_w)}
                              : tensors.tensor[i];
    });
    tensors.tensor = std::move(result);
}

void smooth_dcurv(const SmoothingContext& ctx, float sigma, const std::vector<glm::vec3>& d1,
                  const std::vector<glm::vec3>& d2, std::vector<glm::vec4>& dcurv) {
    if (!(sigma > 0)) return;
    std::vector<glm::vec4> result(dcurv.size());
    for_each_neighbourhood(ctx, sigma, [&](size_t i, const Neighbour* first, const Neighbour* last, double sum_w) {
        glm::dvec4 acc(0.0);
        for (const Neighbour* h = first; h != last; ++h)
            acc += double(h->w) * glm::dvec4(project_dcurv(d1[h->j], d2[h->j], dcurv[h->j], d1[i], d2[i]));
        result[i] = sum_w > 0 ? glm::vec4(acc / sum_w) : dcurv[i];
    });
    dcurv = std::move(result);
}

}  // namespace kappa
