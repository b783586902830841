#include "view_ridges.h"

#include "geometry/lines/zero_crossings.h"
#include "geometry/parallel.h"

#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace kappa {

using namespace lines;

ViewCurvature view_curvature(float k1, float k2, glm::vec4 C, glm::vec3 n, glm::vec3 d1, glm::vec3 d2,
                             glm::vec3 to_eye) {
    // Reciprocals once: this runs per vertex per frame, and without
    // -ffast-math every division is a division.
    const float r = std::max(glm::length(to_eye), 1e-20f), inv_r = 1.0f / r;
    const glm::vec3 v = to_eye * inv_r;
    const float c = glm::dot(n, v);
    const float abs_c = std::max(std::fabs(c), 1e-4f), inv_abs_c = 1.0f / abs_c;
    const glm::vec2 vt(glm::dot(v, d1), glm::dot(v, d2));
    const float s = std::max(glm::length(vt), 1e-6f), inv_s = 1.0f / s;
    const glm::vec2 w = vt * inv_s;
    const float sec_minus_1 = inv_abs_c - 1.0f;
    const glm::mat2 S(k1, 0.0f, 0.0f, k2);
    const glm::mat2 M = glm::mat2(1.0f) + sec_minus_1 * glm::outerProduct(w, w);
    const glm::mat2 Q = S * M;
    const glm::mat2 A = glm::transpose(Q) * Q;
    // Largest eigenvalue of the symmetric A and its eigenvector.
    const float mean = 0.5f * (A[0][0] + A[1][1]);
    const float radius = std::sqrt(A[1][0] * A[1][0] + 0.25f * (A[1][1] - A[0][0]) * (A[1][1] - A[0][0]));
    ViewCurvature vc;
    vc.q1 = mean + radius;
    glm::vec2 e(A[1][1] - vc.q1, -A[1][0]);
    const glm::vec2 e2(-A[1][0], A[0][0] - vc.q1);
    if (glm::dot(e2, e2) > glm::dot(e, e)) e = e2;
    const float e_len2 = glm::dot(e, e);
    vc.t1 = e_len2 > 1e-30f ? e * (1.0f / std::sqrt(e_len2)) : glm::vec2(1, 0);

    const glm::vec2 x = vc.t1;
    const glm::vec2 Sx = S * x;
    const float sign_c = c > 0 ? 1.0f : (c < 0 ? -1.0f : 0.0f);
    const float dc = sign_c * (glm::dot(vt, Sx) + c * glm::dot(vt, x) * inv_r);  // derivative of |cos(theta)|
    const float dsec = -dc * inv_abs_c * inv_abs_c;
    const glm::vec2 dvt = -(x - glm::dot(x, vt) * vt) * inv_r - c * Sx;
    const glm::vec2 dw = (dvt - w * glm::dot(w, dvt)) * inv_s;
    const glm::mat2 dM = dsec * glm::outerProduct(w, w) + sec_minus_1 * (glm::outerProduct(dw, w) + glm::outerProduct(w, dw));
    // C(x, ., .): C111 = a, C112 = b, C122 = c, C222 = d.
    const glm::mat2 dS(C.x * x.x + C.y * x.y, C.y * x.x + C.z * x.y, C.y * x.x + C.z * x.y, C.z * x.x + C.w * x.y);
    const glm::mat2 dQ = dS * M + S * dM;
    vc.dq1 = 2.0f * glm::dot(Q * x, dQ * x) * inv_abs_c;
    return vc;
}

namespace {

using VertexView = ViewRidgeVertex;

// Where on edge (i, j) a quantity of opposite signs crosses zero, from the
// corner with the smaller vertex number (so both triangles agree).
Crossing crossing(const Face& t, int i, int j, const float f[3]) {
    Crossing c;
    c.lo = t[i] < t[j] ? i : j;
    c.hi = c.lo == i ? j : i;
    c.s = std::fabs(f[c.lo]) / std::max(std::fabs(f[c.lo]) + std::fabs(f[c.hi]), 1e-30f);
    return c;
}

// The part of a -> b where the linear strength g (ga, gb at the ends) is positive, faded.
void emit_above(glm::vec3 a, glm::vec3 b, float ga, float gb, float threshold, bool fade, float tolerance,
                std::vector<LineSegment>& out) {
    glm::vec2 range(0, 1);
    if (!clip_positive(ga, gb, range)) return;
    const float g0 = ga + (gb - ga) * range.x, g1 = ga + (gb - ga) * range.y;
    const float ramp = std::max(threshold, 0.05f);
    const float a0 = fade ? std::clamp(g0 / ramp, 0.0f, 1.0f) : 1.0f, a1 = fade ? std::clamp(g1 / ramp, 0.0f, 1.0f) : 1.0f;
    if (std::max(a0, a1) <= 0) return;
    out.push_back({a + (b - a) * range.x, a + (b - a) * range.y, a0, a1, g0 + threshold, g1 + threshold, tolerance});
}

// The corner shared by the two crossed edges, when exactly two of (01, 12, 20) are.
int lone_corner(const bool crossed[3]) { return !crossed[0] ? 2 : (!crossed[1] ? 0 : 1); }

void apparent_ridge(const Face& t, const glm::vec3 p[3], const VertexView* vv[3], const ViewRidgeOptions& o,
                    std::vector<LineSegment>& out) {
    const float q[3] = {vv[0]->view_curv, vv[1]->view_curv, vv[2]->view_curv};
    if (q[0] <= o.ar_threshold && q[1] <= o.ar_threshold && q[2] <= o.ar_threshold) return;
    glm::vec3 tm[3];
    float e[3];
    for (int i = 0; i < 3; ++i) e[i] = vv[i]->dq1, tm[i] = e[i] * vv[i]->t1;  // points to where q1 grows
    const bool crossed[3] = {glm::dot(tm[0], tm[1]) <= 0, glm::dot(tm[1], tm[2]) <= 0, glm::dot(tm[2], tm[0]) <= 0};
    const int n = int(crossed[0]) + int(crossed[1]) + int(crossed[2]);
    if (n < 2) return;
    const glm::vec3 normal = glm::cross(p[1] - p[0], p[2] - p[0]);
    const float tol = half_longest_edge(p);
    if (n == 2) {
        const int l = lone_corner(crossed), a = (l + 1) % 3, b = (l + 2) % 3;
        const Crossing ca = crossing(t, l, a, e), cb = crossing(t, l, b, e);
        const glm::vec3 pa = point_at(ca, p), pb = point_at(cb, p);
        // A maximum: tmax on both sides of the line point towards it (Judd et al., Fig. 6).
        const glm::vec3 perp = glm::cross(normal, pa - pb);
        const float side = glm::dot(p[l] - pa, perp);
        if (glm::dot(tm[l], perp) * side >= 0 || glm::dot(tm[a], perp) * side <= 0 || glm::dot(tm[b], perp) * side <= 0)
            return;
        emit_above(pa, pb, lerp_at(ca, q) - o.ar_threshold, lerp_at(cb, q) - o.ar_threshold, o.ar_threshold, o.fade,
                   tol, out);
        return;
    }
    // Crossings on all three edges: each joined to the centre.
    const glm::vec3 centre = (p[0] + p[1] + p[2]) / 3.0f;
    const float q_centre = (q[0] + q[1] + q[2]) / 3.0f;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const Crossing c = crossing(t, i, j, e);
        const glm::vec3 pc = point_at(c, p);
        const glm::vec3 perp = glm::cross(normal, pc - centre);
        if (glm::dot(tm[i], perp) * glm::dot(p[i] - centre, perp) >= 0 ||
            glm::dot(tm[j], perp) * glm::dot(p[j] - centre, perp) >= 0)
            continue;
        emit_above(pc, centre, lerp_at(c, q) - o.ar_threshold, q_centre - o.ar_threshold, o.ar_threshold, o.fade,
                   tol, out);
    }
}

void principal_highlight(const Face& t, const glm::vec3 p[3], const VertexView* vv[3], const ViewRidgeOptions& o,
                         std::vector<LineSegment>& out) {
    const float lowest = std::min({vv[0]->kmax, vv[1]->kmax, vv[2]->kmax});
    const float highest = std::max({vv[0]->kmax, vv[1]->kmax, vv[2]->kmax});
    if (lowest < 0 && highest > 0) return;  // neither a ridge nor a valley kind
    int ref = 0;
    for (int i = 1; i < 3; ++i)
        if (std::fabs(vv[i]->kmax) > std::fabs(vv[ref]->kmax)) ref = i;
    float f[3];
    for (int i = 0; i < 3; ++i) {
        const float flip = glm::dot(vv[i]->dmax, vv[ref]->dmax) < 0 ? -1.0f : 1.0f;
        if (flip * glm::dot(vv[i]->dmax, vv[ref]->dmax) < 0.70710678f) return;  // dmax turns too fast to follow
        f[i] = flip * vv[i]->v_dmax;
    }
    const bool pos[3] = {f[0] > 0, f[1] > 0, f[2] > 0};
    const bool crossed[3] = {pos[0] != pos[1], pos[1] != pos[2], pos[2] != pos[0]};
    if (!crossed[0] && !crossed[1] && !crossed[2]) return;
    const int l = lone_corner(crossed), a = (l + 1) % 3, b = (l + 2) % 3;
    const Crossing ca = crossing(t, l, a, f), cb = crossing(t, l, b, f);
    const float ph[3] = {vv[0]->ph_strength, vv[1]->ph_strength, vv[2]->ph_strength};
    emit_above(point_at(ca, p), point_at(cb, p), std::fabs(lerp_at(ca, ph)) - o.ph_threshold,
               std::fabs(lerp_at(cb, ph)) - o.ph_threshold, o.ph_threshold, o.fade, half_longest_edge(p), out);
}

}  // namespace

std::vector<ViewRidgeVertex> view_ridge_vertices(const Mesh& mesh, const SurfaceFields& f, glm::vec3 eye,
                                                 float fs, const std::vector<uint8_t>& only) {
    std::vector<ViewRidgeVertex> view(mesh.vertex_count());
    const bool all = only.size() != view.size();
    parallel_for(view.size(), [&](size_t i) {
        if (!all && !only[i]) return;
        const glm::vec3 to_eye = eye - mesh.positions[i];
        const ViewCurvature vc = view_curvature(f.k1[i], f.k2[i], f.dcurv[i], f.normals[i], f.d1[i], f.d2[i], to_eye);
        ViewRidgeVertex& v = view[i];
        v.view_curv = std::sqrt(std::max(vc.q1, 0.0f)) * fs;
        v.t1 = vc.t1.x * f.d1[i] + vc.t1.y * f.d2[i];
        v.dq1 = vc.dq1;
        // rtsc's curv1 is the curvature of larger magnitude (trimesh2's order), not kappa's k1.
        const bool first = std::fabs(f.k1[i]) >= std::fabs(f.k2[i]);
        v.kmax = first ? f.k1[i] : f.k2[i];
        const float kmin = first ? f.k2[i] : f.k1[i];
        v.dmax = first ? f.d1[i] : f.d2[i];
        const glm::vec3 dir = to_eye * (1.0f / std::max(glm::length(to_eye), 1e-20f));
        v.v_dmax = glm::dot(dir, v.dmax);
        v.ph_strength = (v.kmax * v.kmax - kmin * kmin) * glm::dot(f.normals[i], dir) * fs * fs;
    });
    return view;
}

void view_ridges_of_face(const Mesh& mesh, const Face& t, const SurfaceFields& f,
                         const std::vector<ViewRidgeVertex>& view, const ViewRidgeOptions& o,
                         std::vector<LineSegment>& apparent, std::vector<LineSegment>& highlights) {
    if (f.unreliable(t[0]) || f.unreliable(t[1]) || f.unreliable(t[2])) return;
    const glm::vec3 p[3] = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
    const VertexView* vv[3] = {&view[t[0]], &view[t[1]], &view[t[2]]};
    if (o.apparent_ridges) apparent_ridge(t, p, vv, o, apparent);
    if (o.principal_highlights) principal_highlight(t, p, vv, o, highlights);
}

void extract_view_ridges(const Mesh& mesh, const SurfaceFields& f, glm::vec3 eye, const ViewRidgeOptions& o,
                         std::vector<LineSegment>& apparent, std::vector<LineSegment>& highlights) {
    if (!o.apparent_ridges && !o.principal_highlights) return;
    const std::vector<ViewRidgeVertex> view = view_ridge_vertices(mesh, f, eye, o.feature_size);
    for (const Face& t : mesh.faces) view_ridges_of_face(mesh, t, f, view, o, apparent, highlights);
}

}  // namespace kappa
