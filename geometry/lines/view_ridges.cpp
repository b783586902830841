#include "view_ridges.h"

#include "geometry/parallel/lanes.h"
#include "geometry/lines/zero_crossings.h"
#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <type_traits>

namespace kappa {

using namespace lines;

namespace {

// The view-dependent curvature written once for a scalar F = float and for
// F = Lanes, four vertices at once (geometry/parallel/lanes.h).
using lanes::Lanes;
using lanes::larger;
using lanes::magnitude;
using lanes::root;

template <typename F>
struct ViewCurvatureOf {
    F q1, t1x, t1y, dq1;
    F vx, vy, vz;  // the unit direction to the eye
    F c;           // n.v
};

// k1, k2, C = (a, b, c, d), the normal n, principal directions d1, d2 and
// the vector to the eye (tx, ty, tz); derivation in shaders/common/view_curvature.glsl.
template <typename F>
ViewCurvatureOf<F> view_curvature_of(F k1, F k2, F Ca, F Cb, F Cc, F Cd, F nx, F ny, F nz, F d1x, F d1y, F d1z, F d2x,
                                     F d2y, F d2z, F tx, F ty, F tz) {
    ViewCurvatureOf<F> o;
    const F r = larger<F>(root(tx * tx + ty * ty + tz * tz), F{} + 1e-20f), inv_r = 1.0f / r;
    o.vx = tx * inv_r, o.vy = ty * inv_r, o.vz = tz * inv_r;
    const F c = nx * o.vx + ny * o.vy + nz * o.vz;
    o.c = c;
    const F abs_c = larger<F>(magnitude(c), F{} + 1e-4f), inv_abs_c = 1.0f / abs_c;
    const F vt0 = o.vx * d1x + o.vy * d1y + o.vz * d1z, vt1 = o.vx * d2x + o.vy * d2y + o.vz * d2z;
    const F s = larger<F>(root(vt0 * vt0 + vt1 * vt1), F{} + 1e-6f), inv_s = 1.0f / s;
    const F w0 = vt0 * inv_s, w1 = vt1 * inv_s;
    const F sec_minus_1 = inv_abs_c - 1.0f;
    // M = I + (sec - 1) w w^T; Q = S M with S = diag(k1, k2): Q(r, c) = k_r M(r, c).
    const F M00 = 1.0f + sec_minus_1 * w0 * w0, M01 = sec_minus_1 * w0 * w1, M11 = 1.0f + sec_minus_1 * w1 * w1;
    const F Q00 = k1 * M00, Q01 = k1 * M01, Q10 = k2 * M01, Q11 = k2 * M11;
    // A = Q^T Q (symmetric), its largest eigenvalue q1 and eigenvector t1.
    const F A00 = Q00 * Q00 + Q10 * Q10, A01 = Q00 * Q01 + Q10 * Q11, A11 = Q01 * Q01 + Q11 * Q11;
    const F mean = 0.5f * (A00 + A11);
    const F gap = A11 - A00;
    const F radius = root(A01 * A01 + 0.25f * gap * gap);
    o.q1 = mean + radius;
    const F ea0 = A11 - o.q1, ea1 = -A01, eb0 = -A01, eb1 = A00 - o.q1;
    const auto use_b = eb0 * eb0 + eb1 * eb1 > ea0 * ea0 + ea1 * ea1;
    const F e0 = use_b ? eb0 : ea0, e1 = use_b ? eb1 : ea1;
    const F e_len2 = e0 * e0 + e1 * e1;
    const auto has_e = e_len2 > 1e-30f;
    const F inv_e = 1.0f / root(has_e ? e_len2 : F{} + 1.0f);
    o.t1x = has_e ? e0 * inv_e : F{} + 1.0f;
    o.t1y = has_e ? e1 * inv_e : F{};
    // Its derivative along t1 (x below).
    const F x0 = o.t1x, x1 = o.t1y;
    const F Sx0 = k1 * x0, Sx1 = k2 * x1;
    const F sign_c = c > 0.0f ? F{} + 1.0f : (c < 0.0f ? F{} - 1.0f : F{});
    const F dc = sign_c * ((vt0 * Sx0 + vt1 * Sx1) + c * (vt0 * x0 + vt1 * x1) * inv_r);  // of |cos(theta)|
    const F dsec = -dc * inv_abs_c * inv_abs_c;
    const F x_vt = x0 * vt0 + x1 * vt1;
    const F dvt0 = -(x0 - x_vt * vt0) * inv_r - c * Sx0, dvt1 = -(x1 - x_vt * vt1) * inv_r - c * Sx1;
    const F w_dvt = w0 * dvt0 + w1 * dvt1;
    const F dw0 = (dvt0 - w0 * w_dvt) * inv_s, dw1 = (dvt1 - w1 * w_dvt) * inv_s;
    // dM = dsec w w^T + (sec - 1)(dw w^T + w dw^T)
    const F dM00 = dsec * w0 * w0 + sec_minus_1 * (dw0 * w0 + w0 * dw0);
    const F dM01 = dsec * w0 * w1 + sec_minus_1 * (dw0 * w1 + w0 * dw1);
    const F dM11 = dsec * w1 * w1 + sec_minus_1 * (dw1 * w1 + w1 * dw1);
    // dS = C(x, ., .): C111 = a, C112 = b, C122 = c, C222 = d.
    const F dS00 = Ca * x0 + Cb * x1, dS01 = Cb * x0 + Cc * x1, dS11 = Cc * x0 + Cd * x1;
    // dQ = dS M + S dM
    const F dQ00 = dS00 * M00 + dS01 * M01 + k1 * dM00, dQ01 = dS00 * M01 + dS01 * M11 + k1 * dM01;
    const F dQ10 = dS01 * M00 + dS11 * M01 + k2 * dM01, dQ11 = dS01 * M01 + dS11 * M11 + k2 * dM11;
    const F Qx0 = Q00 * x0 + Q01 * x1, Qx1 = Q10 * x0 + Q11 * x1;
    const F dQx0 = dQ00 * x0 + dQ01 * x1, dQx1 = dQ10 * x0 + dQ11 * x1;
    o.dq1 = 2.0f * (Qx0 * dQx0 + Qx1 * dQx1) * inv_abs_c;
    return o;
}

}  // namespace

namespace {

// A ViewRidgeVertex from the view-dependent curvature o (F = float or Lanes),
// in the order of operations of the glm expressions it replaces.
template <typename F>
struct RidgeVertexOf {
    F view_curv, t1x, t1y, t1z, dq1, kmax, dmaxx, dmaxy, dmaxz, v_dmax, ph_strength;
};
template <typename F>
RidgeVertexOf<F> ridge_vertex_of(const ViewCurvatureOf<F>& o, F k1, F k2, F d1x, F d1y, F d1z, F d2x, F d2y, F d2z,
                                 float fs) {
    RidgeVertexOf<F> r;
    r.view_curv = root(larger<F>(o.q1, F{} + 0.0f)) * fs;
    r.t1x = o.t1x * d1x + o.t1y * d2x, r.t1y = o.t1x * d1y + o.t1y * d2y, r.t1z = o.t1x * d1z + o.t1y * d2z;
    r.dq1 = o.dq1;
    // rtsc's curv1 is the curvature of larger magnitude (trimesh2's order), not kappa's k1.
    const auto first = magnitude(k1) >= magnitude(k2);
    r.kmax = first ? k1 : k2;
    const F kmin = first ? k2 : k1;
    r.dmaxx = first ? d1x : d2x, r.dmaxy = first ? d1y : d2y, r.dmaxz = first ? d1z : d2z;
    r.v_dmax = o.vx * r.dmaxx + o.vy * r.dmaxy + o.vz * r.dmaxz;
    r.ph_strength = (r.kmax * r.kmax - kmin * kmin) * o.c * fs * fs;
    return r;
}

}  // namespace

ViewCurvature view_curvature(float k1, float k2, glm::vec4 C, glm::vec3 n, glm::vec3 d1, glm::vec3 d2,
                             glm::vec3 to_eye) {
    const ViewCurvatureOf<float> o = view_curvature_of<float>(k1, k2, C.x, C.y, C.z, C.w, n.x, n.y, n.z, d1.x, d1.y,
                                                               d1.z, d2.x, d2.y, d2.z, to_eye.x, to_eye.y, to_eye.z);
    ViewCurvature vc;
    vc.q1 = o.q1, vc.t1 = {o.t1x, o.t1y}, vc.dq1 = o.dq1;
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

// Both tests end early on most triangles (apparent ridges: 96% of those
// with a strong vertex on bunny-1M), before the corners' positions are read.
void apparent_ridge(const Face& t, const glm::vec3* positions, const VertexView* vv[3], const ViewRidgeOptions& o,
                    std::vector<LineSegment>& out) {
    const float q[3] = {vv[0]->view_curv, vv[1]->view_curv, vv[2]->view_curv};
    if (q[0] <= o.ar_threshold && q[1] <= o.ar_threshold && q[2] <= o.ar_threshold) return;
    glm::vec3 tm[3];
    float e[3];
    for (int i = 0; i < 3; ++i) e[i] = vv[i]->dq1, tm[i] = e[i] * vv[i]->t1;  // points to where q1 grows
    const bool crossed[3] = {glm::dot(tm[0], tm[1]) <= 0, glm::dot(tm[1], tm[2]) <= 0, glm::dot(tm[2], tm[0]) <= 0};
    const int n = int(crossed[0]) + int(crossed[1]) + int(crossed[2]);
    if (n < 2) return;
    const glm::vec3 p[3] = {positions[t[0]], positions[t[1]], positions[t[2]]};
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

void principal_highlight(const Face& t, const glm::vec3* positions, const VertexView* vv[3],
                         const ViewRidgeOptions& o, std::vector<LineSegment>& out) {
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
    const glm::vec3 p[3] = {positions[t[0]], positions[t[1]], positions[t[2]]};
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
    view_ridge_vertices(mesh, f, eye, fs, only, view);
    return view;
}

void view_ridge_vertices(const Mesh& mesh, const SurfaceFields& f, glm::vec3 eye, float fs,
                         const std::vector<uint8_t>& only, std::vector<ViewRidgeVertex>& view) {
    view.resize(mesh.vertex_count());
    parallel_for_ranges(view.size(), [&](size_t begin, size_t end) {
        view_ridge_vertices(mesh, f, eye, fs, only, begin, end, view);
    });
}

void view_ridge_vertices(const Mesh& mesh, const SurfaceFields& f, glm::vec3 eye, float fs,
                         const std::vector<uint8_t>& only, size_t begin, size_t end,
                         std::vector<ViewRidgeVertex>& view) {
    const bool all = only.size() != view.size();
    auto needed = [&](size_t i) { return all || only[i] != 0; };
    // Vertex i from lane j.
    auto store = [&](size_t i, const auto& r, int j) {
        using lanes::lane;
        ViewRidgeVertex& v = view[i];
        v.view_curv = lane(r.view_curv, j);
        v.t1 = {lane(r.t1x, j), lane(r.t1y, j), lane(r.t1z, j)};
        v.dq1 = lane(r.dq1, j);
        v.kmax = lane(r.kmax, j);
        v.dmax = {lane(r.dmaxx, j), lane(r.dmaxy, j), lane(r.dmaxz, j)};
        v.v_dmax = lane(r.v_dmax, j);
        v.ph_strength = lane(r.ph_strength, j);
    };
    const glm::vec3 *p = mesh.positions.data(), *nrm = f.normals.data(), *d1 = f.d1.data(), *d2 = f.d2.data();
    const glm::vec4* C = f.dcurv.data();
    const float *k1 = f.k1.data(), *k2 = f.k2.data();
    size_t i = begin;
    for (; i + 4 <= end; i += 4) {  // four at once
        if (!needed(i) && !needed(i + 1) && !needed(i + 2) && !needed(i + 3)) continue;
        using lanes::gather;
        const Lanes K1 = gather(i, [&](size_t k) { return k1[k]; }), K2 = gather(i, [&](size_t k) { return k2[k]; });
        const Lanes d1x = gather(i, [&](size_t k) { return d1[k].x; }), d1y = gather(i, [&](size_t k) { return d1[k].y; }),
                    d1z = gather(i, [&](size_t k) { return d1[k].z; });
        const Lanes d2x = gather(i, [&](size_t k) { return d2[k].x; }), d2y = gather(i, [&](size_t k) { return d2[k].y; }),
                    d2z = gather(i, [&](size_t k) { return d2[k].z; });
        const auto o = view_curvature_of<Lanes>(
            K1, K2, gather(i, [&](size_t k) { return C[k].x; }), gather(i, [&](size_t k) { return C[k].y; }),
            gather(i, [&](size_t k) { return C[k].z; }), gather(i, [&](size_t k) { return C[k].w; }),
            gather(i, [&](size_t k) { return nrm[k].x; }), gather(i, [&](size_t k) { return nrm[k].y; }),
            gather(i, [&](size_t k) { return nrm[k].z; }), d1x, d1y, d1z, d2x, d2y, d2z,
            gather(i, [&](size_t k) { return eye.x - p[k].x; }), gather(i, [&](size_t k) { return eye.y - p[k].y; }),
            gather(i, [&](size_t k) { return eye.z - p[k].z; }));
        const auto r = ridge_vertex_of<Lanes>(o, K1, K2, d1x, d1y, d1z, d2x, d2y, d2z, fs);
        for (int j = 0; j < 4; ++j)
            if (needed(i + size_t(j))) store(i + size_t(j), r, j);
    }
    for (; i < end; ++i) {  // the rest one by one, with the same arithmetic
        if (!needed(i)) continue;
        const glm::vec3 t = eye - p[i];
        const auto o = view_curvature_of<float>(k1[i], k2[i], C[i].x, C[i].y, C[i].z, C[i].w, nrm[i].x, nrm[i].y,
                                                nrm[i].z, d1[i].x, d1[i].y, d1[i].z, d2[i].x, d2[i].y, d2[i].z, t.x, t.y,
                                                t.z);
        store(i, ridge_vertex_of<float>(o, k1[i], k2[i], d1[i].x, d1[i].y, d1[i].z, d2[i].x, d2[i].y, d2[i].z, fs), 0);
    }
}

void view_ridges_of_face(const Mesh& mesh, const Face& t, const SurfaceFields& f,
                         const std::vector<ViewRidgeVertex>& view, const ViewRidgeOptions& o,
                         std::vector<LineSegment>& apparent, std::vector<LineSegment>& highlights) {
    if (f.unreliable(t[0]) || f.unreliable(t[1]) || f.unreliable(t[2])) return;
    const VertexView* vv[3] = {&view[t[0]], &view[t[1]], &view[t[2]]};
    if (o.apparent_ridges) apparent_ridge(t, mesh.positions.data(), vv, o, apparent);
    if (o.principal_highlights) principal_highlight(t, mesh.positions.data(), vv, o, highlights);
}

void extract_view_ridges(const Mesh& mesh, const SurfaceFields& f, glm::vec3 eye, const ViewRidgeOptions& o,
                         std::vector<LineSegment>& apparent, std::vector<LineSegment>& highlights) {
    if (!o.apparent_ridges && !o.principal_highlights) return;
    const std::vector<ViewRidgeVertex> view = view_ridge_vertices(mesh, f, eye, o.feature_size);
    for (const Face& t : mesh.faces) view_ridges_of_face(mesh, t, f, view, o, apparent, highlights);
}

}  // namespace kappa
