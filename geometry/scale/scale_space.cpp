#include "scale_space.h"

#include "geometry/ldlt.h"
#include "geometry/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

constexpr float kNeighbourhood = 2.5f;  // fits reach 2.5 sigma
constexpr float kPushRadius = 1.25f;    // a vertex takes values from clusters within 1.25 cells
constexpr double kFitTolerance = 1e-3;  // relative pivot below which a fit is refused (collinear neighbours)

float mean_edge_length(const Mesh& mesh) {
    double sum = 0;
    size_t n = 0;
    for (const Face& f : mesh.faces)
        for (int e = 0; e < 3; ++e) {
            const float l = glm::length(mesh.positions[f[(e + 1) % 3]] - mesh.positions[f[e]]);
            if (l > 0 && std::isfinite(l)) {
                sum += l;
                ++n;
            }
        }
    return n ? float(sum / double(n)) : 0.0f;
}

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

// Fields of one level (steps 1-3 of the header).
ScaleLevelFields fit_level(const ClusterLevel& level) {
    const size_t n = level.size();
    const float sigma = level.cell, radius = kNeighbourhood * sigma;
    const float inv2s2 = 1.0f / (2.0f * sigma * sigma);
    ScaleLevelFields out;
    out.normal.resize(n);
    out.curvature.resize(n);
    out.dcurv.resize(n);
    out.valid.assign(n, 0);

    std::vector<glm::vec3> dir(n);
    for (size_t c = 0; c < n; ++c) {
        const float len = glm::length(level.normal_sum[c]);
        dir[c] = len > 0 && std::isfinite(len) ? level.normal_sum[c] / len : glm::vec3(0.0f);
    }

    // 1. Normals.
    parallel_for_ranges(n, [&](size_t first, size_t last) {
        Neighbourhood nb;
        for (size_t p = first; p < last; ++p) {
            glm::dvec3 sum(0.0);
            if (dir[p] != glm::vec3(0.0f))
                nb.visit(level, dir, uint32_t(p), radius, [&](uint32_t q, float d2) {
                    sum += double(level.area[q] * std::exp(-d2 * inv2s2)) * glm::dvec3(dir[q]);
                });
            const double len = glm::length(sum);
            out.normal[p] = len > 0 ? glm::vec3(sum / len) : glm::vec3(0, 0, 1);
        }
    }, 256);

    // 2. Curvature: II e = dn in the tangent frame of each cluster.
    parallel_for_ranges(n, [&](size_t first, size_t last) {
        Neighbourhood nb;
        for (size_t p = first; p < last; ++p) {
            if (dir[p] == glm::vec3(0.0f)) continue;
            glm::vec3 u, v;
            tangent_frame(out.normal[p], u, v);
            double diag[3] = {0, 0, 0}, off[2] = {0, 0}, rhs[3] = {0, 0, 0};
            nb.visit(level, dir, uint32_t(p), radius, [&](uint32_t q, float d2) {
                if (q == p) return;
                const double w = double(level.area[q]) * std::exp(-d2 * inv2s2);
                const glm::vec3 e = level.centroid[q] - level.centroid[p];
                const glm::vec3 dn = out.normal[q] - out.normal[p];
                const double e1 = glm::dot(e, u), e2 = glm::dot(e, v);
                const double n1 = glm::dot(dn, u), n2 = glm::dot(dn, v);
                diag[0] += w * e1 * e1;
                diag[1] += w * (e1 * e1 + e2 * e2);
                diag[2] += w * e2 * e2;
                off[0] += w * e1 * e2;
                off[1] += w * e1 * e2;
                rhs[0] += w * e1 * n1;
                rhs[1] += w * (e2 * n1 + e1 * n2);
                rhs[2] += w * e2 * n2;
            });
            double x[3];
            if (ldlt_solve_tridiagonal<3>(diag, off, rhs, x, kFitTolerance)) {
                out.curvature[p] = Tensor2{float(x[0]), float(x[1]), float(x[2])};
                out.valid[p] = 1;
            }
        }
    }, 256);

    // 3. C: C(e) = dII, with the neighbours' tensors moved into p's frame.
    parallel_for_ranges(n, [&](size_t first, size_t last) {
        Neighbourhood nb;
        for (size_t p = first; p < last; ++p) {
            if (!out.valid[p]) continue;
            glm::vec3 u, v;
            tangent_frame(out.normal[p], u, v);
            const Tensor2 t0 = out.curvature[p];
            double diag[4] = {0, 0, 0, 0}, off[3] = {0, 0, 0}, rhs[4] = {0, 0, 0, 0};
            nb.visit(level, dir, uint32_t(p), radius, [&](uint32_t q, float d2) {
                if (q == p || !out.valid[q]) return;
                const double w = double(level.area[q]) * std::exp(-d2 * inv2s2);
                glm::vec3 uq, vq;
                tangent_frame(out.normal[q], uq, vq);
                const Tensor2 tq = project_tensor(uq, vq, out.curvature[q], u, v);
                const glm::vec3 e = level.centroid[q] - level.centroid[p];
                const double e1 = glm::dot(e, u), e2 = glm::dot(e, v);
                const double duu = tq.ku - t0.ku, duv = tq.kuv - t0.kuv, dvv = tq.kv - t0.kv;
                diag[0] += w * e1 * e1;
                diag[1] += w * (e1 * e1 + e2 * e2);
                diag[2] += w * (e1 * e1 + e2 * e2);
                diag[3] += w * e2 * e2;
                for (double& o : off) o += w * e1 * e2;
                rhs[0] += w * e1 * duu;
                rhs[1] += w * (e2 * duu + e1 * duv);
                rhs[2] += w * (e2 * duv + e1 * dvv);
                rhs[3] += w * e2 * dvv;
            });
            double x[4];
            if (ldlt_solve_tridiagonal<4>(diag, off, rhs, x, kFitTolerance))
                out.dcurv[p] = glm::vec4(float(x[0]), float(x[1]), float(x[2]), float(x[3]));
        }
    }, 256);
    return out;
}

// One level's share of a vertex's fields: the clusters it takes values
// from and their weights (the vertex's cluster and the adjacent ones,
// weighted by area x (1 - (d / R)^2)^2, R = 1.25 cells).
struct LevelSample {
    static constexpr int kMax = 48;
    uint32_t cluster[kMax];
    float weight[kMax];
    int count = 0;
    glm::vec3 normal{0.0f};  // unit weighted mean normal
};

bool sample_level(const ClusterLevel& level, const ScaleLevelFields& fields, uint32_t vertex, const glm::vec3& p,
                  LevelSample& s) {
    const uint32_t home = level.vertex_cluster[vertex];
    const float r = kPushRadius * level.cell, inv_r2 = 1.0f / (r * r);
    s.count = 0;
    double wsum = 0;
    glm::dvec3 nsum(0.0);
    auto take = [&](uint32_t q) {
        if (!fields.valid[q] || s.count == LevelSample::kMax) return;
        const glm::vec3 d = level.centroid[q] - p;
        const float x = 1.0f - glm::dot(d, d) * inv_r2;
        if (x <= 0) return;
        const float w = level.area[q] * x * x;
        if (!(w > 0)) return;
        s.cluster[s.count] = q;
        s.weight[s.count++] = w;
        wsum += w;
        nsum += double(w) * glm::dvec3(fields.normal[q]);
    };
    take(home);
    for (uint32_t k = level.adj_offsets[home]; k < level.adj_offsets[home + 1]; ++k) take(level.adj[k]);
    if (s.count == 0 && fields.valid[home]) {  // a vertex far out in its cell: its cluster alone
        s.cluster[0] = home;
        s.weight[0] = 1;
        s.count = 1;
        wsum = 1;
        nsum = glm::dvec3(fields.normal[home]);
    }
    if (s.count == 0) return false;
    for (int i = 0; i < s.count; ++i) s.weight[i] = float(s.weight[i] / wsum);
    const double len = glm::length(nsum);
    if (!(len > 0)) return false;
    s.normal = glm::vec3(nsum / len);
    return true;
}

}  // namespace

ScaleSpace build_scale_space(const Mesh& mesh, const SurfaceFields& raw) {
    ScaleSpace space;
    const float h = mean_edge_length(mesh);
    space.raw_scale = 0.5f * h;
    if (!(h > 0)) return space;
    glm::vec3 lo = mesh.positions[0], hi = lo;
    for (const auto& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const float radius = 0.5f * glm::length(hi - lo);
    space.pyramid = build_cluster_pyramid(mesh, raw.point_areas, raw.normals, 2.0f * h, radius);
    space.levels.resize(space.pyramid.levels.size());
    for (size_t l = 0; l < space.levels.size(); ++l) space.levels[l] = fit_level(space.pyramid.levels[l]);
    return space;
}

namespace {

// A vertex's blend of two neighbouring estimates: level lo (-1: the raw
// estimate) with share[0], level lo + 1 with share[1], linear in log sigma.
struct VertexBlend {
    int lo = -1;
    float share[2] = {1, 0};
    LevelSample samples[2];
    bool use[2] = {false, false};  // false: the raw estimate stands in for that level
    glm::vec3 normal{0.0f};        // unit blended normal; zero when there is none
};

// Fills `b` for vertex v at scale sigma; returns false where the raw fields
// are kept as they are (flagged vertex, sigma at or below the raw scale).
bool blend_vertex(const Mesh& mesh, const ScaleSpace& space, const SurfaceFields& raw, size_t v, float sigma,
                  VertexBlend& b) {
    const size_t levels = space.levels.size();
    if (levels == 0 || raw.unreliable(v) || !(sigma > space.raw_scale)) return false;
    // Level coordinate: -1 for the raw estimate, l for level l.
    const float log_first = std::log2(space.level_scale(0)), log_raw = std::log2(space.raw_scale);
    const float ls = std::log2(sigma);
    float lambda = ls < log_first ? -1.0f + (ls - log_raw) / (log_first - log_raw) : ls - log_first;
    lambda = std::min(lambda, float(levels - 1));
    b.lo = int(std::floor(lambda));
    const float t = lambda - float(b.lo);
    b.share[0] = 1.0f - t;
    b.share[1] = t;
    glm::vec3 n(0.0f);
    for (int i = 0; i < 2; ++i) {
        const int l = b.lo + i;
        b.use[i] = false;
        if (b.share[i] <= 0.0f) continue;
        if (l >= 0 && sample_level(space.pyramid.levels[size_t(l)], space.levels[size_t(l)], uint32_t(v),
                                   mesh.positions[v], b.samples[i])) {
            b.use[i] = true;
            n += b.share[i] * b.samples[i].normal;
        } else {
            n += b.share[i] * raw.normals[v];
        }
    }
    const float len = glm::length(n);
    if (!(len > 0)) return false;
    b.normal = n / len;
    return true;
}

}  // namespace

SurfaceFields fields_at_scale(const Mesh& mesh, const ScaleSpace& space, const SurfaceFields& raw,
                              const std::vector<float>& sigma) {
    SurfaceFields out = raw;
    parallel_for(mesh.vertex_count(), [&](size_t v) {
        VertexBlend b;
        if (!blend_vertex(mesh, space, raw, v, sigma[v], b)) return;
        const glm::vec3 n = b.normal;
        glm::vec3 u, w;
        tangent_frame(n, u, w);
        Tensor2 tensor{0, 0, 0};
        glm::vec4 dcurv(0.0f);
        auto add = [&](float weight, const glm::vec3& fu, const glm::vec3& fv, const Tensor2& t, const glm::vec4& c) {
            const Tensor2 r = project_tensor(fu, fv, t, u, w);
            tensor.ku += weight * r.ku;
            tensor.kuv += weight * r.kuv;
            tensor.kv += weight * r.kv;
            dcurv += weight * project_dcurv(fu, fv, c, u, w);
        };
        for (int i = 0; i < 2; ++i) {
            if (b.share[i] <= 0.0f) continue;
            if (!b.use[i]) {
                add(b.share[i], raw.d1[v], raw.d2[v], Tensor2{raw.k1[v], 0, raw.k2[v]}, raw.dcurv[v]);
                continue;
            }
            const ScaleLevelFields& f = space.levels[size_t(b.lo + i)];
            for (int k = 0; k < b.samples[i].count; ++k) {
                const uint32_t q = b.samples[i].cluster[k];
                glm::vec3 qu, qv;
                tangent_frame(f.normal[q], qu, qv);
                add(b.share[i] * b.samples[i].weight[k], qu, qv, f.curvature[q], f.dcurv[q]);
            }
        }
        out.normals[v] = n;
        diagonalize_tensor(u, w, n, tensor, out.d1[v], out.d2[v], out.k1[v], out.k2[v]);
        out.dcurv[v] = project_dcurv(u, w, dcurv, out.d1[v], out.d2[v]);
    }, 2048);
    return out;
}

std::vector<glm::vec3> normals_at_scale(const Mesh& mesh, const ScaleSpace& space, const SurfaceFields& raw,
                                        const std::vector<float>& sigma) {
    std::vector<glm::vec3> out = raw.normals;
    parallel_for(mesh.vertex_count(), [&](size_t v) {
        VertexBlend b;
        if (blend_vertex(mesh, space, raw, v, sigma[v], b)) out[v] = b.normal;
    }, 2048);
    return out;
}

SurfaceFields fields_at_scale(const Mesh& mesh, const ScaleSpace& space, const SurfaceFields& raw, float sigma) {
    return fields_at_scale(mesh, space, raw, std::vector<float>(mesh.vertex_count(), sigma));
}

}  // namespace kappa
