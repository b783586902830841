#include "scale_space.h"

#include "geometry/parallel/parallel.h"
#include "tensor3.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

constexpr float kPushRadius = 1.25f;  // a vertex takes values from clusters within 1.25 cells

// One level's value at a vertex: the kernel-weighted mean over the
// vertex's cluster and the adjacent ones, weight area x (1 - (d / R)^2)^2
// with R = 1.25 cells. Sums; normal() and mean() finish them.
struct LevelValue {
    float weight = 0;
    glm::vec3 normal_sum{0.0f};
    Sym3 curvature;
    SymCubic3 dcurv;
    // Positions: the weighted sum of the moves that bring the vertex onto
    // each cluster's fitted surface, over the clusters facing the vertex's
    // own (not the far side of a thin sheet); shift() finishes it.
    float shift_weight = 0;
    glm::vec3 shift_sum{0.0f};
    glm::vec3 shift() const { return shift_weight > 0 ? shift_sum / shift_weight : glm::vec3(0.0f); }
};

// What a blend computes besides the normal.
enum class Blend { Normals, Positions, Tensors };

// Returns false when no cluster around the vertex has a fit.
template <Blend kBlend>
bool level_value(const ClusterLevel& level, const ScaleLevelFields& fields, uint32_t vertex, const glm::vec3& p,
                 LevelValue& out) {
    const uint32_t home = level.vertex_cluster[vertex];
    const glm::vec3 facing = fields.value[home].normal;
    const float r = kPushRadius * level.cell, inv_r2 = 1.0f / (r * r);
    out = LevelValue{};
    // Each cluster's value is carried from its centroid to the vertex to
    // first order (dn = II dp, dII = C(dp)), so the blend has no bias from
    // where the clusters happen to sit around the vertex.
    auto take = [&](uint32_t q, float w) {
        const ScaleLevelFields::Value& s = fields.value[q];
        const glm::vec3 d = p - glm::vec3(fields.place[q]);
        out.weight += w;
        out.normal_sum += w * (s.normal + apply(s.curvature, d));
        if (kBlend == Blend::Positions && glm::dot(s.normal, facing) > 0) {
            // The cluster's surface: n . (x - c) = height - II(t, t) / 2.
            const float above = glm::dot(s.normal, d) - (fields.height[q] - 0.5f * sym3_eval(s.curvature, d, d));
            out.shift_weight += w;
            out.shift_sum -= w * above * s.normal;
        }
        if (kBlend == Blend::Tensors) {
            add_scaled(out.curvature, w, s.curvature);
            add_scaled(out.curvature, w, contract(s.dcurv, d));
            add_scaled(out.dcurv, w, s.dcurv);
        }
    };
    auto weigh = [&](uint32_t q) {
        const glm::vec4& s = fields.place[q];
        const glm::vec3 d = glm::vec3(s) - p;
        return scale_kernel(s.w, glm::dot(d, d), inv_r2);  // area 0 where the fit failed
    };
    if (const float w = weigh(home); w > 0) take(home, w);
    for (uint32_t k = level.adj_offsets[home]; k < level.adj_offsets[home + 1]; ++k)
        if (const float w = weigh(level.adj[k]); w > 0) take(level.adj[k], w);
    if (!(out.weight > 0) && fields.valid[home]) take(home, 1.0f);  // far out in its cell: its cluster alone
    return out.weight > 0 && glm::length(out.normal_sum) > 0;
}

// A level's value at a vertex as the cache keeps it: the sums the blend reads, 20 floats for the
// curvature blend, 8 for the surface's.
template <Blend kBlend>
void pack_value(const LevelValue& v, float* out) {
    out[0] = v.weight;
    for (int k = 0; k < 3; ++k) out[1 + k] = v.normal_sum[k];
    if (kBlend == Blend::Tensors) {
        std::copy(v.curvature.m, v.curvature.m + 6, out + 4);
        std::copy(v.dcurv.c, v.dcurv.c + 10, out + 10);
    } else {
        out[4] = v.shift_weight;
        for (int k = 0; k < 3; ++k) out[5 + k] = v.shift_sum[k];
    }
}

template <Blend kBlend>
void unpack_value(const float* in, LevelValue& v) {
    v = LevelValue{};
    v.weight = in[0];
    v.normal_sum = {in[1], in[2], in[3]};
    if (kBlend == Blend::Tensors) {
        std::copy(in + 4, in + 10, v.curvature.m);
        std::copy(in + 10, in + 20, v.dcurv.c);
    } else {
        v.shift_weight = in[4];
        v.shift_sum = {in[5], in[6], in[7]};
    }
}

// level_value through the space's cache for this blend (level_value_cache.h): computed and kept on a
// vertex's first blend at the level, read back after.
template <Blend kBlend>
bool cached_level_value(const ScaleSpace& space, size_t l, uint32_t v, const glm::vec3& p, LevelValue& out) {
    const LevelValueCache& cache = kBlend == Blend::Tensors ? space.tensor_values : space.surface_values;
    uint8_t* states = kBlend == Blend::Normals ? nullptr : cache.states(l);
    if (!states) return level_value<kBlend>(space.clusters[l], space.levels[l], v, p, out);
    float* kept = cache.values(l) + size_t(v) * cache.floats();
    if (states[v] == LevelValueCache::Unknown) {
        const bool usable = level_value<kBlend>(space.clusters[l], space.levels[l], v, p, out);
        if (usable) pack_value<kBlend>(out, kept);
        states[v] = usable ? LevelValueCache::Usable : LevelValueCache::Unusable;
        return usable;
    }
    if (states[v] == LevelValueCache::Unusable) return false;
    unpack_value<kBlend>(kept, out);
    return true;
}

// Before a blend that reads the levels `read`: room in `cache` for those of them that are fitted.
void prepare_cache(const Mesh& mesh, const ScaleSpace& space, LevelValueCache& cache, std::vector<size_t> read);

// Level coordinate of a scale: -1 for the raw estimate, l for level l,
// linear in log sigma in between; clamped to the top level.
float level_coordinate(const ScaleSpace& space, float sigma) {
    const float log_first = std::log2(space.level_scale(0)), log_raw = std::log2(space.raw_scale);
    const float ls = std::log2(std::max(sigma, space.raw_scale));
    const float lambda = ls < log_first ? -1.0f + (ls - log_raw) / (log_first - log_raw) : ls - log_first;
    return std::min(lambda, float(space.levels.size() - 1));
}

// A vertex's blend of two neighbouring estimates: level lo (-1: the raw
// estimate) with share[0], level lo + 1 with share[1].
struct VertexBlend {
    int lo = -1;
    float share[2] = {1, 0};
    LevelValue value[2];
    bool use[2] = {false, false};  // false: the raw estimate stands in for that level
    glm::vec3 normal{0.0f};        // unit blended normal
};

// Fills `b` for vertex v at scale sigma; returns false where the raw fields
// are kept as they are (flagged vertex, sigma at or below the raw scale).
template <Blend kBlend>
bool blend_vertex(const Mesh& mesh, const ScaleSpace& space, const SurfaceFields& raw, size_t v, float sigma,
                  VertexBlend& b) {
    if (space.levels.empty() || raw.unreliable(v) || !(sigma > space.raw_scale)) return false;
    const float lambda = level_coordinate(space, sigma);
    b.lo = int(std::floor(lambda));
    const float t = lambda - float(b.lo);
    b.share[0] = 1.0f - t;
    b.share[1] = t;
    glm::vec3 n(0.0f);
    for (int i = 0; i < 2; ++i) {
        const int l = b.lo + i;
        b.use[i] = false;
        if (b.share[i] <= 0.0f) continue;
        if (l >= 0 && space.levels[size_t(l)].fitted() &&
            cached_level_value<kBlend>(space, size_t(l), uint32_t(v), mesh.positions[v], b.value[i])) {
            b.use[i] = true;
            n += b.share[i] * glm::normalize(b.value[i].normal_sum);
        } else {
            n += b.share[i] * raw.normals[v];
        }
    }
    const float len = glm::length(n);
    if (!(len > 0) || !std::isfinite(len)) return false;
    b.normal = n / len;
    return true;
}

// The levels that scales in [lo, hi] blend from: level floor(lambda) and the next one, lambda the
// level coordinate of each scale (none when all are at or below the raw scale).
std::vector<size_t> blended_levels(const ScaleSpace& space, float lo, float hi) {
    std::vector<size_t> levels;
    if (space.levels.empty() || !(hi > space.raw_scale) || std::isnan(lo)) return levels;
    const int first = std::max(0, int(std::floor(level_coordinate(space, lo))));
    const int last = int(std::ceil(level_coordinate(space, hi)));
    for (int l = first; l <= last && l < int(space.levels.size()); ++l) levels.push_back(size_t(l));
    return levels;
}

// The levels that the scales sigma[v] of vertices [first, last) blend from.
std::vector<size_t> levels_read(const ScaleSpace& space, const std::vector<float>& sigma, size_t first, size_t last) {
    if (first >= last) return {};
    const auto [lo, hi] = std::minmax_element(sigma.begin() + long(first), sigma.begin() + long(last));
    return blended_levels(space, *lo, *hi);
}

void prepare_cache(const Mesh& mesh, const ScaleSpace& space, LevelValueCache& cache, std::vector<size_t> read) {
    if (!cache.enabled() || read.empty()) return;
    read.erase(std::remove_if(read.begin(), read.end(), [&](size_t l) { return !space.levels[l].fitted(); }),
               read.end());
    cache.prepare(space.levels.size(), mesh.vertex_count(), read);
}

// The levels that scales in [lo, hi] blend from and that are not fitted yet.
std::vector<size_t> unfitted_levels(const ScaleSpace& space, float lo, float hi) {
    std::vector<size_t> todo = blended_levels(space, lo, hi);
    todo.erase(std::remove_if(todo.begin(), todo.end(), [&](size_t l) { return space.levels[l].fitted(); }),
               todo.end());
    return todo;
}

}  // namespace

namespace {

// The vertices grouped by their cluster of `level`, each group in vertex order (a counting sort).
void make_visit_order(ScaleSpace& space, size_t level) {
    const ClusterLevel& c = space.clusters[level];
    std::vector<uint32_t> start(c.size() + 1, 0);
    for (const uint32_t k : c.vertex_cluster) ++start[k + 1];
    for (size_t k = 0; k < c.size(); ++k) start[k + 1] += start[k];
    space.visit_order.resize(c.vertex_cluster.size());
    for (size_t v = 0; v < c.vertex_cluster.size(); ++v) space.visit_order[start[c.vertex_cluster[v]]++] = uint32_t(v);
    space.visit_order_level = level;
}

// Calls body(v) for the vertices [first, last) on the threads: in the space's visit order when it
// covers them all and the finest of the levels `read` has over a 64th as many clusters
// as there are vertices (then its clusters' values are what misses the cache: on a 17.8M-face
// mesh the fine normals took 1.9-2.0 s instead of 2.8-3.0 s; coarser levels stay in the cache,
// and the vertices' own arrays read and written out of order cost more: 2.3-2.9 s instead of
// 1.9 s for its fields at 12 px).
template <typename Body>
void for_vertices(const ScaleSpace& space, const std::vector<size_t>& read, size_t first, size_t last, Body&& body) {
    const bool ordered = first == 0 && last == space.visit_order.size() && !read.empty() &&
                         space.clusters[read.front()].size() * 64 >= last;
    parallel_for(last - first, [&](size_t k) { body(ordered ? size_t(space.visit_order[k]) : first + k); }, 2048);
}

}  // namespace

void fit_levels(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw, const std::vector<size_t>& todo) {
    // Clustering runs on one thread per level: build the levels side by side.
    parallel_for(todo.size(), [&](size_t k) {
        const size_t i = todo[k];
        if (!space.clusters[i].built())
            space.clusters[i] =
                build_surface_clusters(mesh, raw.point_areas, raw.normals, space.origin, space.level_scale(i));
    }, 1);
    if (const auto finest = std::min_element(todo.begin(), todo.end());
        finest != todo.end() && *finest < space.visit_order_level)
        make_visit_order(space, *finest);
    for (size_t i : todo) space.levels[i] = fit_level(space.clusters[i]);
    parallel_for(todo.size(), [&](size_t k) {
        const size_t i = todo[k];
        fit_level_heights(space.clusters[i], mesh.positions, raw.point_areas, space.levels[i]);
    }, 1);
}

namespace {

void fit_levels_for(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw, const std::vector<float>& sigma) {
    fit_levels(mesh, space, raw, levels_to_fit(space, sigma));
}

}  // namespace

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

ScaleSpace build_scale_space(const Mesh& mesh) {
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
    space.first_cell = 1.5f * h;
    space.origin = lo;
    // Up to a quarter of the bounding radius: coarser, a few clusters would
    // stand for the whole model.
    size_t levels = 1;
    while (space.level_scale(levels) <= 0.25f * radius && levels < 30) ++levels;
    space.clusters.resize(levels);
    space.levels.resize(levels);
    return space;
}

bool uses_raw_estimate(const ScaleSpace& space, const std::vector<float>& sigma) {
    if (space.empty()) return true;
    const float first = space.level_scale(0);
    return std::any_of(sigma.begin(), sigma.end(), [&](float s) { return !(s >= first); });
}

void fit_all_levels(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw) {
    fit_levels(mesh, space, raw, unfitted_levels(space, space.raw_scale, space.max_scale()));
}

std::vector<size_t> levels_to_fit(const ScaleSpace& space, const std::vector<float>& sigma) {
    if (sigma.empty()) return {};
    const auto [lo, hi] = std::minmax_element(sigma.begin(), sigma.end());
    return unfitted_levels(space, *lo, *hi);
}

LevelFitSteps::LevelFitSteps(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw, size_t level,
                             size_t chunk)
    : mesh_(mesh), space_(space), raw_(raw), level_(level), chunk_(chunk) {}

bool LevelFitSteps::done() const { return space_.levels[level_].fitted(); }

void LevelFitSteps::step() {
    if (done()) return;
    ClusterLevel& clusters = space_.clusters[level_];
    if (!clusters.built()) {
        clusters = build_surface_clusters(mesh_, raw_.point_areas, raw_.normals, space_.origin,
                                          space_.level_scale(level_));
        return;
    }
    if (!fitter_) fitter_ = std::make_unique<LevelFitter>(clusters, chunk_);
    if (!fitter_->done()) return fitter_->step();
    ScaleLevelFields fields = fitter_->take();
    fit_level_heights(clusters, mesh_.positions, raw_.point_areas, fields);
    space_.levels[level_] = std::move(fields);  // fitted only now, heights and all
    fitter_.reset();
}

SurfaceFields fields_to_blend(const Mesh& mesh, const SurfaceFields& raw) {
    SurfaceFields out;
    out.normals = raw.normals;
    out.point_areas = raw.point_areas;
    out.flags = raw.flags;
    out.smoothing = raw.smoothing;
    out.noise = raw.noise;
    if (raw.has_curvature()) {
        out.k1 = raw.k1, out.k2 = raw.k2, out.d1 = raw.d1, out.d2 = raw.d2, out.dcurv = raw.dcurv;
    } else {  // zero where only the raw estimate could say (flagged vertices)
        const size_t n = mesh.vertex_count();
        out.k1.assign(n, 0.0f), out.k2.assign(n, 0.0f), out.dcurv.assign(n, glm::vec4(0.0f));
        out.d1.resize(n), out.d2.resize(n);
        for (size_t v = 0; v < n; ++v) tangent_frame(raw.normals[v], out.d1[v], out.d2[v]);
    }
    return out;
}

void blend_fields(const Mesh& mesh, const ScaleSpace& space, const SurfaceFields& raw,
                  const std::vector<float>& sigma, size_t first, size_t last, SurfaceFields& out) {
    const std::vector<size_t> read = levels_read(space, sigma, first, last);
    prepare_cache(mesh, space, space.tensor_values, read);
    const bool has_raw = raw.has_curvature();
    for_vertices(space, read, first, last, [&](size_t v) {
        VertexBlend b;
        if (!blend_vertex<Blend::Tensors>(mesh, space, raw, v, sigma[v], b)) return;
        Sym3 tensor;
        SymCubic3 dcurv;
        for (int i = 0; i < 2; ++i) {
            if (b.share[i] <= 0.0f) continue;
            if (b.use[i]) {
                const float w = b.share[i] / b.value[i].weight;
                add_scaled(tensor, w, b.value[i].curvature);
                add_scaled(dcurv, w, b.value[i].dcurv);
            } else if (has_raw) {
                add_scaled(tensor, b.share[i], embed(Tensor2{raw.k1[v], 0, raw.k2[v]}, raw.d1[v], raw.d2[v]));
                add_scaled(dcurv, b.share[i], embed(raw.dcurv[v], raw.d1[v], raw.d2[v]));
            }
        }
        const glm::vec3 n = b.normal;
        glm::vec3 u, w;
        tangent_frame(n, u, w);
        out.normals[v] = n;
        diagonalize_tensor(u, w, n, restrict_to(tensor, u, w), out.d1[v], out.d2[v], out.k1[v], out.k2[v]);
        out.dcurv[v] = restrict_to(dcurv, out.d1[v], out.d2[v]);
    });
}

SurfaceFields fields_at_scale(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw,
                              const std::vector<float>& sigma) {
    fit_levels_for(mesh, space, raw, sigma);
    SurfaceFields out = fields_to_blend(mesh, raw);
    blend_fields(mesh, space, raw, sigma, 0, mesh.vertex_count(), out);
    return out;
}

std::vector<glm::vec3> normals_at_scale(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw,
                                        const std::vector<float>& sigma) {
    fit_levels_for(mesh, space, raw, sigma);
    std::vector<glm::vec3> out = raw.normals;
    const size_t n = mesh.vertex_count();
    for_vertices(space, levels_read(space, sigma, 0, n), 0, n, [&](size_t v) {
        VertexBlend b;
        if (blend_vertex<Blend::Normals>(mesh, space, raw, v, sigma[v], b)) out[v] = b.normal;
    });
    return out;
}

void blend_surface(const Mesh& mesh, const ScaleSpace& space, const SurfaceFields& raw,
                   const std::vector<float>& sigma, size_t first, size_t last, SurfaceAtScale& out) {
    const std::vector<size_t> read = levels_read(space, sigma, first, last);
    prepare_cache(mesh, space, space.surface_values, read);
    for_vertices(space, read, first, last, [&](size_t v) {
        VertexBlend b;
        if (!blend_vertex<Blend::Positions>(mesh, space, raw, v, sigma[v], b)) return;
        out.normals[v] = b.normal;
        glm::vec3 shift(0.0f);  // the raw estimate's share stays where it is
        for (int i = 0; i < 2; ++i)
            if (b.use[i]) shift += b.share[i] * b.value[i].shift();
        // Never further than the scale itself: a vertex keeps to its own
        // neighbourhood whatever a poor fit says.
        const float len = glm::length(shift);
        if (len > sigma[v]) shift *= sigma[v] / len;
        if (std::isfinite(len)) out.positions[v] += shift;
    });
}

SurfaceAtScale surface_at_scale(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw,
                                const std::vector<float>& sigma) {
    fit_levels_for(mesh, space, raw, sigma);
    SurfaceAtScale out{mesh.positions, raw.normals};
    blend_surface(mesh, space, raw, sigma, 0, mesh.vertex_count(), out);
    return out;
}

SurfaceFields fields_at_scale(const Mesh& mesh, ScaleSpace& space, const SurfaceFields& raw, float sigma) {
    return fields_at_scale(mesh, space, raw, std::vector<float>(mesh.vertex_count(), sigma));
}

}  // namespace kappa
