#include "level_fit.h"

#include "geometry/curvature/ldlt.h"
#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

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

// The neighbourhoods of clusters [first, last) (Neighbourhood::visit within
// R), with kernel weights, appended to nb's compressed rows. Each thread
// gathers a contiguous range; the ranges are appended in order, so the rows
// depend neither on the thread count nor on how the clusters are split into calls.
void gather_neighbourhoods(const ClusterLevel& level, const std::vector<glm::vec3>& dir, float radius, size_t first,
                           size_t last, LevelFitter::NeighbourLists& nb) {
    const size_t n = last - first;
    const float inv_r2 = 1.0f / (radius * radius);
    const size_t chunks = std::max<size_t>(1, std::min<size_t>(64, n / 1024));
    std::vector<LevelFitter::NeighbourLists> parts(chunks);
    // One visitor a thread at a time rather than one a chunk: each fills its stamps (a word per
    // cluster) once per call.
    std::mutex pool_lock;
    std::vector<std::unique_ptr<Neighbourhood>> pool;
    parallel_for(chunks, [&](size_t c) {
        const size_t from = first + n * c / chunks, to = first + n * (c + 1) / chunks;
        LevelFitter::NeighbourLists& part = parts[c];
        part.offsets.reserve(to - from);
        std::unique_ptr<Neighbourhood> taken;
        {
            const std::lock_guard<std::mutex> hold(pool_lock);
            if (!pool.empty()) taken = std::move(pool.back()), pool.pop_back();
        }
        if (!taken) taken = std::make_unique<Neighbourhood>();
        Neighbourhood& visitor = *taken;
        for (size_t p = from; p < to; ++p) {
            if (dir[p] != glm::vec3(0.0f))
                visitor.visit(level, dir, uint32_t(p), radius, [&](uint32_t q, float d2) {
                    const float w = scale_kernel(level.area[q], d2, inv_r2);
                    if (w > 0 || q == p) {
                        part.cluster.push_back(q);
                        part.weight.push_back(w);
                    }
                });
            part.offsets.push_back(uint32_t(part.cluster.size()));
        }
        const std::lock_guard<std::mutex> hold(pool_lock);
        pool.push_back(std::move(taken));
    }, 1);
    if (nb.offsets.empty()) nb.offsets.push_back(0);
    for (const LevelFitter::NeighbourLists& part : parts) {
        const uint32_t base = uint32_t(nb.cluster.size());
        for (uint32_t end : part.offsets) nb.offsets.push_back(base + end);
        nb.cluster.insert(nb.cluster.end(), part.cluster.begin(), part.cluster.end());
        nb.weight.insert(nb.weight.end(), part.weight.begin(), part.weight.end());
    }
}

// Calls body(p) for p in [first, last) on the threads.
template <typename Body>
void for_clusters(size_t first, size_t last, Body&& body) {
    parallel_for(last - first, [&](size_t i) { body(first + i); }, 1024);
}

}  // namespace

LevelFitter::LevelFitter(const ClusterLevel& level, size_t chunk) : level_(level), chunk_(chunk) {
    const size_t n = level.size();
    out_.value.resize(n);
    out_.valid.assign(n, 0);
    dir_.resize(n);
    for (size_t c = 0; c < n; ++c) {
        const float len = glm::length(level.normal_sum[c]);
        dir_[c] = len > 0 && std::isfinite(len) ? level.normal_sum[c] / len : glm::vec3(0.0f);
    }
    curvature_.resize(n);
    nb_.offsets.reserve(n + 1);
    if (n == 0) finish();
}

void LevelFitter::step() {
    if (done()) return;
    const size_t n = level_.size();
    const size_t first = next_, last = chunk_ == 0 ? n : std::min(n, first + chunk_);
    switch (phase_) {
        case Phase::Neighbourhoods: gather_neighbourhoods(level_, dir_, kNeighbourhood * level_.cell, first, last, nb_); break;
        case Phase::Normals: fit_normals(first, last); break;
        case Phase::Curvature: fit_curvature(first, last); break;
        case Phase::Dcurv: fit_dcurv(first, last); break;
        case Phase::Done: break;
    }
    next_ = last;
    if (next_ < n) return;
    next_ = 0;
    if (phase_ == Phase::Dcurv) finish();
    else phase_ = Phase(int(phase_) + 1);
}

// 1. Normals.
void LevelFitter::fit_normals(size_t first, size_t last) {
    for_clusters(first, last, [&](size_t p) {
        glm::vec3 sum(0.0f);
        for (uint32_t k = nb_.offsets[p]; k < nb_.offsets[p + 1]; ++k) sum += nb_.weight[k] * dir_[nb_.cluster[k]];
        const float len = glm::length(sum);
        out_.value[p].normal = len > 0 && std::isfinite(len) ? sum / len : glm::vec3(0, 0, 1);
    });
}

// 2. Curvature: II e = dn in the tangent frame of each cluster.
void LevelFitter::fit_curvature(size_t first, size_t last) {
    for_clusters(first, last, [&](size_t p) {
        if (dir_[p] == glm::vec3(0.0f)) return;
        glm::vec3 u, v;
        tangent_frame(out_.value[p].normal, u, v);
        double diag[3] = {0, 0, 0}, off[2] = {0, 0}, rhs[3] = {0, 0, 0};
        for (uint32_t k = nb_.offsets[p]; k < nb_.offsets[p + 1]; ++k) {
            const uint32_t q = nb_.cluster[k];
            const float w = nb_.weight[k];
            const glm::vec3 e = level_.centroid[q] - level_.centroid[p];
            const glm::vec3 dn = out_.value[q].normal - out_.value[p].normal;
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
            curvature_[p] = Tensor2{float(x[0]), float(x[1]), float(x[2])};
            out_.value[p].curvature = embed(curvature_[p], u, v);
            out_.valid[p] = 1;
        }
    });
}

// 3. C: C(e) = dII, the neighbours' tensors restricted to p's frame.
void LevelFitter::fit_dcurv(size_t first, size_t last) {
    for_clusters(first, last, [&](size_t p) {
        if (!out_.valid[p]) return;
        glm::vec3 u, v;
        tangent_frame(out_.value[p].normal, u, v);
        const Tensor2 t0 = curvature_[p];
        double diag[4] = {0, 0, 0, 0}, off[3] = {0, 0, 0}, rhs[4] = {0, 0, 0, 0};
        for (uint32_t k = nb_.offsets[p]; k < nb_.offsets[p + 1]; ++k) {
            const uint32_t q = nb_.cluster[k];
            if (!out_.valid[q]) continue;
            const float w = nb_.weight[k];
            const Tensor2 tq = restrict_to(out_.value[q].curvature, u, v);
            const glm::vec3 e = level_.centroid[q] - level_.centroid[p];
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
            out_.value[p].dcurv = embed(glm::vec4(float(x[0]), float(x[1]), float(x[2]), float(x[3])), u, v);
    });
}

void LevelFitter::finish() {
    // Where each cluster's value sits and how much it weighs (fields_at_scale).
    const size_t n = level_.size();
    out_.place.resize(n);
    for (size_t p = 0; p < n; ++p) out_.place[p] = glm::vec4(level_.centroid[p], out_.valid[p] ? level_.area[p] : 0.0f);
    phase_ = Phase::Done;
}

ScaleLevelFields LevelFitter::take() { return std::move(out_); }

ScaleLevelFields fit_level(const ClusterLevel& level) {
    LevelFitter fitter(level);
    while (!fitter.done()) fitter.step();
    return fitter.take();
}

void fit_level_heights(const ClusterLevel& level, const std::vector<glm::vec3>& positions,
                       const std::vector<float>& point_areas, ScaleLevelFields& fields) {
    // height = mean over the cluster's vertices of n . d + II(t, t) / 2; the
    // mean of n . d is zero at the area-weighted centroid, but is kept: the
    // centroid's float sums round.
    // Each cluster's sums in vertex order whatever the threads: each thread scans every vertex and
    // sums those of its own range of clusters.
    const size_t clusters = level.size();
    std::vector<double> sum(clusters, 0.0), weight(clusters, 0.0);
    parallel_for_ranges(clusters, [&](size_t lo, size_t hi) {
        for (size_t v = 0; v < positions.size(); ++v) {
            const uint32_t q = level.vertex_cluster[v];
            if (q < lo || q >= hi || !fields.valid[q] || !(point_areas[v] > 0)) continue;
            const glm::vec3 d = positions[v] - level.centroid[q];
            const glm::vec3& n = fields.value[q].normal;
            sum[q] += double(point_areas[v]) * (glm::dot(n, d) + 0.5f * sym3_eval(fields.value[q].curvature, d, d));
            weight[q] += point_areas[v];
        }
    }, 4096);
    fields.height.assign(clusters, 0.0f);
    parallel_for(clusters, [&](size_t q) {
        if (weight[q] > 0) fields.height[q] = float(sum[q] / weight[q]);
    });
}

}  // namespace kappa
