#include "render/lines/cluster_culling.h"

#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace kappa::render {

std::vector<VertexBounds> vertex_bounds(const SurfaceFields& fields, float fs) {
    const double fs2 = double(fs) * double(fs);
    std::vector<VertexBounds> out(fields.k1.size());
    parallel_for(out.size(), [&](size_t v) {
        VertexBounds& b = out[v];
        const float k1 = fields.k1[v], k2 = fields.k2[v];
        const float kmax = std::max(std::fabs(k1), std::fabs(k2)), kmin = std::min(std::fabs(k1), std::fabs(k2));
        b.kmax = kmax * fs;
        b.highlight = (kmax * kmax - kmin * kmin) * fs * fs;
        b.strength = dcurv_norm(glm::dvec4(fields.dcurv[v])) * fs2;
        b.reliable = !fields.unreliable(v);
        b.k2_positive = k2 > 0, b.k1_negative = k1 < 0;
        b.positive_k = k1 * k2 > 0.0f, b.positive_h = 0.5f * (k1 + k2) > 0.0f;
    });
    return out;
}

MeshClusters mesh_cluster_bounds(const Mesh& mesh, const SurfaceFields& fields, const FaceClusters& clusters,
                                 const std::vector<glm::vec3>& fine_normals) {
    MeshClusters out;
    if (fine_normals.empty()) {
        out.bounds = compute_cluster_bounds(mesh, fields.normals, clusters);
    } else {
        auto both = compute_cluster_bounds_for_sets(mesh, {&fields.normals, &fine_normals}, clusters);
        out.bounds = std::move(both[0]), out.fine_bounds = std::move(both[1]);
    }
    out.first_face = clusters.cluster_start;
    if (out.first_face.empty()) out.first_face = {0};
    out.may_have_suggestive.assign(clusters.size(), 0);
    out.max_strength.assign(clusters.size(), 0.0f);
    out.may_have_parabolic.assign(clusters.size(), 0);
    out.may_have_mean_zero.assign(clusters.size(), 0);
    out.max_kmax.assign(clusters.size(), 0.0f);
    out.max_highlight.assign(clusters.size(), 0.0f);
    return out;
}

void bound_cluster_curvature(const Mesh& mesh, const FaceClusters& clusters, const std::vector<VertexBounds>& vb,
                             size_t first, size_t last, MeshClusters& out) {
    // Clusters are independent: each writes only its own entries.
    parallel_for(last - first, [&](size_t k) {
        const size_t c = first + k;
        double strength = 0;
        for (uint32_t i = clusters.cluster_start[c]; i < clusters.cluster_start[c + 1]; ++i) {
            const Face& f = mesh.faces[clusters.face_order[i]];
            const VertexBounds* corner[3] = {&vb[f[0]], &vb[f[1]], &vb[f[2]]};
            bool reliable = true, elliptic_up = true, elliptic_down = true;
            for (const VertexBounds* b : corner) {
                reliable = reliable && b->reliable;
                elliptic_up = elliptic_up && b->k2_positive;     // k1 >= k2 > 0: kr > 0
                elliptic_down = elliptic_down && b->k1_negative;  // k2 <= k1 < 0: kr < 0
            }
            if (reliable) {  // the curvature lines' bounds
                int positive_k = 0, positive_h = 0;
                for (const VertexBounds* b : corner) {
                    positive_k += b->positive_k, positive_h += b->positive_h;
                    out.max_kmax[c] = std::max(out.max_kmax[c], b->kmax);
                    out.max_highlight[c] = std::max(out.max_highlight[c], b->highlight);
                }
                if (positive_k % 3 != 0) out.may_have_parabolic[c] = 1;
                if (positive_h % 3 != 0) out.may_have_mean_zero[c] = 1;
            }
            if (!reliable || elliptic_up || elliptic_down) continue;
            out.may_have_suggestive[c] = 1;
            for (const VertexBounds* b : corner) strength = std::max(strength, b->strength);
        }
        // Float evaluation in the shader: a margin well above its rounding.
        out.max_strength[c] = float(strength * (1 + 1e-4) + 1e-30);
    }, 64);
}

MeshClusters make_mesh_clusters(const Mesh& mesh, const SurfaceFields& fields, const FaceClusters& clusters,
                                float feature_size, const std::vector<glm::vec3>& fine_normals) {
    MeshClusters out = mesh_cluster_bounds(mesh, fields, clusters, fine_normals);
    bound_cluster_curvature(mesh, clusters, vertex_bounds(fields, feature_size), 0, clusters.size(), out);
    return out;
}

namespace {

// The side and near planes of the clip volume, the sides widened by
// `margin` (in NDC units), or of the part of it over the NDC rectangle
// [lo, hi], as model-space planes a.p + d >= 0 (Gribb and Hartmann 2001).
// The far plane frames the whole model and is left out.
struct Frustum {
    glm::vec4 planes[5];

    Frustum(const glm::mat4& mvp, glm::vec2 margin) : Frustum(mvp, -(1.0f + margin), 1.0f + margin) {}
    Frustum(const glm::mat4& mvp, glm::vec2 lo, glm::vec2 hi) {
        auto row = [&](int i) { return glm::vec4(mvp[0][i], mvp[1][i], mvp[2][i], mvp[3][i]); };
        const glm::vec4 x = row(0), y = row(1), z = row(2), w = row(3);
        planes[0] = w * -lo.x + x;  // x >= lo.x w
        planes[1] = w * hi.x - x;   // x <= hi.x w
        planes[2] = w * -lo.y + y;
        planes[3] = w * hi.y - y;
        planes[4] = w + z;  // in front of the near plane
    }
    bool may_touch(const ClusterBounds& b) const {
        for (const glm::vec4& p : planes)
            if (glm::dot(glm::vec3(p), b.center) + p.w < -b.radius * glm::length(glm::vec3(p))) return false;
        return true;
    }
};

// Adds cluster c's faces to the runs, extending the last run when they follow it.
void append_cluster(std::vector<FaceRun>& runs, const MeshClusters& clusters, size_t c) {
    const uint32_t first = clusters.first_face[c], count = clusters.first_face[c + 1] - first;
    if (!runs.empty() && runs.back().first + runs.back().count == first)
        runs.back().count += count;
    else
        runs.push_back({first, count});
}

}  // namespace

std::vector<FaceRun> contour_pass_runs(const MeshClusters& clusters, const FrameParams& frame, bool contours,
                                       bool suggestive, float sc_threshold, float margin_px, bool any_front) {
    const Frustum frustum(frame.mvp, 2.0f * margin_px / frame.viewport);
    std::vector<FaceRun> runs;
    for (size_t c = 0; c < clusters.size(); ++c) {
        const ClusterBounds& b = clusters.bounds[c];
        if (!frustum.may_touch(b)) continue;
        const Facing facing = classify_facing(b, frame.eye);
        const Facing contour_facing =
            clusters.fine_bounds.empty() ? facing : classify_facing(clusters.fine_bounds[c], frame.eye);
        const bool draw = (any_front && facing != Facing::Back) || (contours && contour_facing == Facing::Mixed) ||
                          (suggestive && clusters.may_have_suggestive[c] &&
                           (facing == Facing::Mixed || (facing == Facing::Front && clusters.max_strength[c] > sc_threshold)));
        if (draw) append_cluster(runs, clusters, c);
    }
    return runs;
}

namespace {

// The clusters in the view (less the entirely back-facing ones unless
// back_facing) for which keep(cluster index) holds.
template <typename Keep>
std::vector<FaceRun> visible_runs_where(const MeshClusters& clusters, const FrameParams& frame, bool back_facing,
                                        float margin_px, Keep keep) {
    const Frustum frustum(frame.mvp, 2.0f * margin_px / frame.viewport);
    std::vector<FaceRun> runs;
    for (size_t c = 0; c < clusters.size(); ++c) {
        const ClusterBounds& b = clusters.bounds[c];
        if (frustum.may_touch(b) && (back_facing || classify_facing(b, frame.eye) != Facing::Back) && keep(c))
            append_cluster(runs, clusters, c);
    }
    return runs;
}

// Whether [lo, hi] holds one of the levels first + k step, k = 0 .. count - 1
// (with a margin for float rounding in the shader).
bool holds_level(float lo, float hi, const LevelSet& levels) {
    const float margin = 1e-4f * levels.step;
    const float k0 = std::ceil((lo - margin - levels.first) / levels.step);
    const float k1 = std::floor((hi + margin - levels.first) / levels.step);
    return k0 <= k1 && k1 >= 0 && k0 <= float(levels.count - 1);
}

}  // namespace

std::vector<FaceRun> front_surface_runs(const MeshClusters& clusters, const FrameParams& frame) {
    return visible_runs_where(clusters, frame, false, 0.0f, [](size_t) { return true; });
}

std::vector<FaceRun> back_facing_runs_in(const MeshClusters& clusters, const FrameParams& frame,
                                         const std::vector<glm::ivec4>& rects) {
    std::vector<Frustum> frusta;  // one a rectangle, its pixels' edges in NDC
    for (const glm::ivec4& r : rects) {
        const glm::vec2 lo = glm::vec2(r.x, r.y) / frame.viewport * 2.0f - 1.0f;
        const glm::vec2 hi = glm::vec2(r.x + r.z, r.y + r.w) / frame.viewport * 2.0f - 1.0f;
        frusta.emplace_back(frame.mvp, lo, hi);
    }
    std::vector<FaceRun> runs;
    for (size_t c = 0; c < clusters.size(); ++c) {
        const ClusterBounds& b = clusters.bounds[c];
        if (classify_facing(b, frame.eye) == Facing::Front) continue;  // every face culled anyway
        if (std::any_of(frusta.begin(), frusta.end(), [&](const Frustum& f) { return f.may_touch(b); }))
            append_cluster(runs, clusters, c);
    }
    return runs;
}

// The shaders compare float values with these bounds: a margin well above their rounding.
constexpr float kBoundMargin = 1.0f + 1e-4f;

std::vector<FaceRun> curvature_line_runs(const MeshClusters& clusters, const FrameParams& frame, bool back_facing,
                                         float margin_px, const LineSelection& lines, float rv_threshold) {
    return visible_runs_where(clusters, frame, back_facing, margin_px, [&](size_t c) {
        return (lines.parabolic && clusters.may_have_parabolic[c]) ||
               (lines.mean_zero && clusters.may_have_mean_zero[c]) ||
               ((lines.ridges || lines.valleys) && clusters.max_kmax[c] * kBoundMargin > rv_threshold);
    });
}

std::vector<FaceRun> view_ridge_runs(const MeshClusters& clusters, const FrameParams& frame, bool back_facing,
                                     float margin_px, const LineSelection& lines, float ph_threshold) {
    return visible_runs_where(clusters, frame, back_facing, margin_px, [&](size_t c) {
        return lines.apparent_ridges ||
               (lines.principal_highlights && clusters.max_highlight[c] * kBoundMargin > ph_threshold);
    });
}

std::vector<FaceRun> isophote_runs(const MeshClusters& clusters, const FrameParams& frame, bool back_facing,
                                   float margin_px, glm::vec3 light, const LevelSet& levels) {
    return visible_runs_where(clusters, frame, back_facing, margin_px, [&](size_t c) {
        const ClusterBounds& b = clusters.bounds[c];
        if (b.cos_angle <= -1.0f) return true;  // normals in every direction
        // n.l for n within angle a of the axis: the angle to l lies in [beta - a, beta + a].
        const float beta = std::acos(std::clamp(glm::dot(b.axis, light), -1.0f, 1.0f));
        const float a = std::acos(std::clamp(b.cos_angle, -1.0f, 1.0f));
        const float hi = std::cos(std::max(0.0f, beta - a)), lo = std::cos(std::min(float(M_PI), beta + a));
        return holds_level(lo - 1e-4f, hi + 1e-4f, levels);
    });
}

std::vector<FaceRun> topo_runs(const MeshClusters& clusters, const FrameParams& frame, bool back_facing,
                               float margin_px, const LevelSet& levels) {
    return visible_runs_where(clusters, frame, back_facing, margin_px, [&](size_t c) {
        const ClusterBounds& b = clusters.bounds[c];
        return holds_level(b.center.y - b.radius, b.center.y + b.radius, levels);
    });
}

}  // namespace kappa::render
