#include "level_fit.h"

#include "geometry/curvature/ldlt.h"
#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

constexpr float kNeighbourhood = 2.0f;  // fits reach 2 cells
constexpr double kFitTolerance = 1e-3;  // relative pivot below which a fit is refused (collinear neighbours)

// Calls visit(Q, d2) for cluster P itself and every cluster Q within
// `radius` of P's centroid that is reached from P through adjacent clusters
// within the radius and whose mean normal faces P's (dir[P] . dir[Q] > 0).
struct Neighbourhood {
    std::vector<uint32_t> stamp, stack;

    template <typename Visit>
    void visit(const ClusterLevel& level, const std::vector<glm::vec3>& dir, uint32_t p, float radius, Visit&& fn) {
        if (stamp.size() != level.size()) stamp.assign(level.size(), UINT32_MAX);
        const float r2 = radius * radius;
        const glm::vec3 c0 = level.centroid[p];
        stack.assign(1, p);
        stamp[p] = p;
        while (!stack.empty()) {
            const uint32_t q = stack.back();
            stack.pop_back();
            const glm::vec3 d = level.centroid[q] - c0;
            const float d2 = glm::dot(d, d);
            if (q != p && (d2 >= r2 || glm::dot(dir[p], dir[q]) <= 0.0f)) continue;
            fn(q, d2);
            for (uint32_t k = level.adj_offsets[q]; k < level.adj_offsets[q + 1]; ++k) {
                const uint32_t nb = level.adj[k];
                if (stamp[nb] != p) {
                    stamp[nb] = p;
                    stack.push_back(nb);
                }
            }
        }
    }
};

// Every cluster's fit neighbourhood (Neighbourhood::visit within R), with
// kernel weights, in compressed rows: gathered once, used by all three fits.
struct NeighbourLists {
    std::vector<uint32_t> offsets, cluster;
    std::vector<float> weight;
};

NeighbourLists gather_neighbourhoods(const ClusterLevel& level, const std::vector<glm::vec3>& dir, float radius) {
    const size_t n = level.size();
    const float inv_r2 = 1.0f / (radius * radius);
    // Each thread gathers a contiguous range of clusters; the ranges are
    // concatenated in order, so the lists do not depend on the thread count.
    const size_t chunks = std::max<size_t>(1, std::min<size_t>(64, n / 1024));
    std::vector<NeighbourLists> parts(chunks);
    parallel_for(chunks, [&](size_t c) {
        const size_t first = n * c / chunks, last = n * (c + 1) / chunks;
        NeighbourLists& part = parts[c];
        part.offsets.reserve(last - first);
        Neighbourhood nb;
        for (size_t p = first; p < last; ++p) {
            if (dir[p] != glm::vec3(0.0f))
                nb.visit(level, dir, uint32_t(p), radius, [&](uint32_t q, float d2) {
                    const float w = scale_kernel(level.area[q], d2, inv_r2);
                    if (w > 0 || q == p) {
                        part.cluster.push_back(q);
                        part.weight.push_back(w);
                    }
                });
            part.offsets.push_back(uint32_t(part.cluster.size()));
        }
    }, 1);
    NeighbourLists out;
    out.offsets.reserve(n + 1);
    out.offsets.push_back(0);
    for (const NeighbourLists& part : parts) {
        const uint32_t base = uint32_t(out.cluster.size());
        for (uint32_t end : part.offsets) out.offsets.push_back(base + end);
        out.cluster.insert(out.cluster.end(), part.cluster.begin(), part.cluster.end());
        out.weight.insert(out.weight.end(), part.weight.begin(), part.weight.end());
    }
    return out;
}

}  // namespace

ScaleLevelFields fit_level(const ClusterLevel& level) {
    const size_t n = level.size();
    ScaleLevelFields out;
    out.value.resize(n);
    out.valid.assign(n, 0);

    std::vector<glm::vec3> dir(n);
    for (size_t c = 0; c < n; ++c) {
        const float len = glm::length(level.normal_sum[c]);
        dir[c] = len > 0 && std::isfinite(len) ? level.normal_sum[c] / len : glm::vec3(0.0f);
    }
    const NeighbourLists nb = gather_neighbourhoods(level, dir, kNeighbourhood * level.cell);

    // 1. Normals.
    parallel_for(n, [&](size_t p) {
        glm::vec3 sum(0.0f);
        for (uint32_t k = nb.offsets[p]; k < nb.offsets[p + 1]; ++k) sum += nb.weight[k] * dir[nb.cluster[k]];
        const float len = glm::length(sum);
        out.value[p].normal = len > 0 && std::isfinite(len) ? sum / len : glm::vec3(0, 0, 1);
    }, 1024);

    // 2. Curvature: II e = dn in the tangent frame of each cluster.
    std::vector<Tensor2> curvature(n);
    parallel_for(n, [&](size_t p) {
        if (dir[p] == glm::vec3(0.0f)) return;
        glm::vec3 u, v;
        tangent_frame(out.value[p].normal, u, v);
        double diag[3] = {0, 0, 0}, off[2] = {0, 0}, rhs[3] = {0, 0, 0};
        for (uint32_t k = nb.offsets[p]; k < nb.offsets[p + 1]; ++k) {
            const uint32_t q = nb.cluster[k];
            const float w = nb.weight[k];
            const glm::vec3 e = level.centroid[q] - level.centroid[p];
            const glm::vec3 dn = out.value[q].normal - out.value[p].normal;
            const float e1 = glm::dot(e, u), e2 = glm::dot(e, v);
            const float n1 = glm::dot(dn, u), n2 = glm::dot(dn, v);
            diag[0] += w * e1 * e1;
            diag[1] += w * (e1 * e1 + e2 * e2);
            diag[2] += w * e2 * e2;
            off[0] += w * e1 * e2;
            rhs[0] += w * e1 * n1;
            rhs[1] += w * (e2 * n1 + e1 * n2);
            rhs[2] += w * e2 * n2;
        }
        off[1] = off[0];
        double x[3];
        if (ldlt_solve_tridiagonal<3>(diag, off, rhs, x, kFitTolerance)) {
            curvature[p] = Tensor2{float(x[0]), float(x[1]), float(x[2])};
            out.value[p].curvature = embed(curvature[p], u, v);
            out.valid[p] = 1;
        }
    }, 1024);

    // 3. C: C(e) = dII, the neighbours' tensors restricted to p's frame.
    parallel_for(n, [&](size_t p) {
        if (!out.valid[p]) return;
        glm::vec3 u, v;
        tangent_frame(out.value[p].normal, u, v);
        const Tensor2 t0 = curvature[p];
        double diag[4] = {0, 0, 0, 0}, off[3] = {0, 0, 0}, rhs[4] = {0, 0, 0, 0};
        for (uint32_t k = nb.offsets[p]; k < nb.offsets[p + 1]; ++k) {
            const uint32_t q = nb.cluster[k];
            if (!out.valid[q]) continue;
            const float w = nb.weight[k];
            const Tensor2 tq = restrict_to(out.value[q].curvature, u, v);
            const glm::vec3 e = level.centroid[q] - level.centroid[p];
            const float e1 = glm::dot(e, u), e2 = glm::dot(e, v);
            const float duu = tq.ku - t0.ku, duv = tq.kuv - t0.kuv, dvv = tq.kv - t0.kv;
            diag[0] += w * e1 * e1;
            diag[1] += w * (e1 * e1 + e2 * e2);
            diag[3] += w * e2 * e2;
            off[0] += w * e1 * e2;
            rhs[0] += w * e1 * duu;
            rhs[1] += w * (e2 * duu + e1 * duv);
            rhs[2] += w * (e2 * duv + e1 * dvv);
            rhs[3] += w * e2 * dvv;
        }
        diag[2] = diag[1];
        off[1] = off[2] = off[0];
        double x[4];
        if (ldlt_solve_tridiagonal<4>(diag, off, rhs, x, kFitTolerance))
            out.value[p].dcurv = embed(glm::vec4(float(x[0]), float(x[1]), float(x[2]), float(x[3])), u, v);
    }, 1024);

    // Where each cluster's value sits and how much it weighs (fields_at_scale).
    out.place.resize(n);
    for (size_t p = 0; p < n; ++p) out.place[p] = glm::vec4(level.centroid[p], out.valid[p] ? level.area[p] : 0.0f);
    return out;
}

void fit_level_heights(const ClusterLevel& level, const std::vector<glm::vec3>& positions,
                       const std::vector<float>& point_areas, ScaleLevelFields& fields) {
    // height = mean over the cluster's vertices of n . d + II(t, t) / 2; the
    // mean of n . d is zero at the area-weighted centroid, but is kept: the
    // centroid's float sums round.
    std::vector<double> sum(level.size(), 0.0), weight(level.size(), 0.0);
    for (size_t v = 0; v < positions.size(); ++v) {
        const uint32_t q = level.vertex_cluster[v];
        if (q >= level.size() || !fields.valid[q] || !(point_areas[v] > 0)) continue;
        const glm::vec3 d = positions[v] - level.centroid[q];
        const glm::vec3& n = fields.value[q].normal;
        sum[q] += double(point_areas[v]) * (glm::dot(n, d) + 0.5f * sym3_eval(fields.value[q].curvature, d, d));
        weight[q] += point_areas[v];
    }
    fields.height.assign(level.size(), 0.0f);
    for (size_t q = 0; q < level.size(); ++q)
        if (weight[q] > 0) fields.height[q] = float(sum[q] / weight[q]);
}

}  // namespace kappa
