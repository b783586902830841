// Analytic test surfaces with their true curvature, and the curvature error
// measure of Rusinkiewicz 2004 (Fig. 8), for tests of noise and smoothing.
//
// Error: RMS over vertices and tangent directions of the normal-curvature
// error, divided by the RMS over vertices and directions of the true normal
// curvature. Both tensors are compared in the true normal's tangent frame
// (u, v); for a symmetric 2x2 tensor E there, the mean over directions
// (c, s) of (E11 c^2 + 2 E12 c s + E22 s^2)^2 is
// (3 E11^2 + 3 E22^2 + 2 E11 E22 + 4 E12^2) / 8.
#pragma once

#include "geometry/mesh/edge_table.h"
#include "geometry/mesh/mesh.h"
#include "geometry/mesh/mesh_stats.h"
#include "geometry/mesh/primitives.h"
#include "geometry/surface_fields.h"
#include "geometry/curvature/tensor_frames.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace kappa::test {

// A mesh with the true unit normal and shape operator S (3x3, world
// coordinates, tangent to n: the normal curvature along a unit tangent t is
// t.S t; II = dN, convex positive) at each vertex; `weight` 0 excludes a
// vertex from the error (a patch's margin). `dcurv`: the true C = (C111,
// C112, C122, C222) in the frame tangent_frame(normal).
struct AnalyticMesh {
    Mesh mesh;
    std::vector<glm::dvec3> normal;
    std::vector<glm::dmat3> shape;
    std::vector<float> weight;
    std::vector<glm::dvec4> dcurv;
};

// C of a frame (e1, e2) re-expressed in the vertex frame tangent_frame(n):
// the new basis vectors' coordinates in (e1, e2) give the frame change.
inline glm::dvec4 dcurv_in_tangent_frame(const glm::dvec4& C, const glm::dvec3& e1, const glm::dvec3& e2,
                                         const glm::dvec3& n) {
    glm::vec3 fu, fv;
    tangent_frame(glm::vec3(n), fu, fv);
    const glm::dvec3 u(fu), v(fv);
    const double m[2][2] = {{glm::dot(u, e1), glm::dot(u, e2)}, {glm::dot(v, e1), glm::dot(v, e2)}};
    auto tri = [&](int a, int b, int c) {  // C(m_a, m_b, m_c) with C stored by the number of e2 slots
        double r = 0;
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
                for (int k = 0; k < 2; ++k) r += C[i + j + k] * m[a][i] * m[b][j] * m[c][k];
        return r;
    };
    return {tri(0, 0, 0), tri(0, 0, 1), tri(0, 1, 1), tri(1, 1, 1)};
}

// True C of an implicit surface F = 0 at a point with unit normal n =
// grad F / |grad F|, from F's Hessian H and third derivative T (T(a, b, c)):
// locally z = f(x, y) over the tangent plane with f_i = 0, and implicit
// differentiation gives f_ij = -F_ij / F_z and
// f_ijk = -(F_ijk + F_iz f_jk + F_jz f_ik + F_kz f_ij) / F_z, z along n;
// II = -f_ij and C = -f_ijk there (II = dN, convex positive). Independent
// of the estimators' own formulas (geometry/curvature/graph_geometry.h).
template <typename Third>
glm::dvec4 implicit_dcurv(const glm::dvec3& n, double grad_len, const glm::dmat3& H, const Third& T) {
    glm::vec3 fu, fv;
    tangent_frame(glm::vec3(n), fu, fv);
    const glm::dvec3 e[2] = {glm::dvec3(fu), glm::dvec3(fv)};
    double f2[2][2], hz[2];
    for (int i = 0; i < 2; ++i) {
        hz[i] = glm::dot(e[i], H * n);
        for (int j = 0; j < 2; ++j) f2[i][j] = -glm::dot(e[i], H * e[j]) / grad_len;
    }
    auto f3 = [&](int i, int j, int k) {
        return -(T(e[i], e[j], e[k]) + hz[i] * f2[j][k] + hz[j] * f2[i][k] + hz[k] * f2[i][j]) / grad_len;
    };
    return {-f3(0, 0, 0), -f3(0, 0, 1), -f3(0, 1, 1), -f3(1, 1, 1)};
}

inline glm::dmat3 outer(const glm::dvec3& a, const glm::dvec3& b) {
    glm::dmat3 m;
    for (int c = 0; c < 3; ++c) m[c] = a * b[c];  // column c
    return m;
}

// Torus of make_torus: curvature 1/r along the tube, cos v / (R + r cos v)
// along the big circle (conventions.md). C in the principal frame (tu, tv):
// only C(tu, tu, tv) = d(cos v / rho) / (r dv) = -R sin v / (r rho^2) is
// non-zero (rho = R + r cos v). With `jitter` > 0 every vertex moves by up
// to jitter cells in each angle, staying on the torus (an irregular
// tessellation; deterministic for a seed).
inline AnalyticMesh analytic_torus(double R, double r, int nu, int nv, double jitter = 0, uint32_t seed = 1) {
    AnalyticMesh a{make_torus(float(R), float(r), nu, nv), {}, {}, {}, {}};
    std::mt19937 rng(seed);
    auto uniform = [&] { return double(rng()) / 4294967295.0 * 2.0 - 1.0; };  // [-1, 1]
    const double two_pi = 2 * glm::pi<double>();
    for (auto& p : a.mesh.positions) {
        double u = std::atan2(double(p.y), double(p.x));
        double v = std::atan2(double(p.z), std::hypot(double(p.x), double(p.y)) - R);
        if (jitter > 0) {
            u += jitter * two_pi / nu * uniform();
            v += jitter * two_pi / nv * uniform();
            const double rho = R + r * std::cos(v);
            p = glm::vec3(float(rho * std::cos(u)), float(rho * std::sin(u)), float(r * std::sin(v)));
        }
        const double rho = R + r * std::cos(v);
        const glm::dvec3 n(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
        const glm::dvec3 tv(-std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v));
        const glm::dvec3 tu(-std::sin(u), std::cos(u), 0.0);
        a.normal.push_back(n);
        a.shape.push_back((1.0 / r) * outer(tv, tv) + (std::cos(v) / rho) * outer(tu, tu));
        a.weight.push_back(1.0f);
        a.dcurv.push_back(dcurv_in_tangent_frame({0, -R * std::sin(v) / (r * rho * rho), 0, 0}, tu, tv, n));
    }
    return a;
}

// Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 of make_ellipsoid: with F the
// left side, n = grad F / |grad F| and S = P H P / |grad F|, H = Hessian of
// F, P = I - n n^T.
// With `jitter` > 0, every vertex first moves in a random direction by up to
// jitter times 1/2^levels (about an edge), then back onto the ellipsoid
// along the ray from the centre: a random tessellation. C: F is quadratic,
// so T = 0 in implicit_dcurv.
inline AnalyticMesh analytic_ellipsoid(double ea, double eb, double ec, int levels, double jitter = 0,
                                       uint32_t seed = 1) {
    AnalyticMesh a{make_ellipsoid(float(ea), float(eb), float(ec), levels), {}, {}, {}, {}};
    const glm::dvec3 h(2 / (ea * ea), 2 / (eb * eb), 2 / (ec * ec));
    std::mt19937 rng(seed);
    auto uniform = [&] { return double(rng()) / 4294967295.0 * 2.0 - 1.0; };  // [-1, 1]
    const double step = jitter * std::max(ea, std::max(eb, ec)) / double(1 << levels);
    for (auto& p : a.mesh.positions) {
        if (jitter > 0) {
            glm::dvec3 q = glm::dvec3(p) + step * glm::dvec3(uniform(), uniform(), uniform());
            q /= std::sqrt(q.x * q.x / (ea * ea) + q.y * q.y / (eb * eb) + q.z * q.z / (ec * ec));
            p = glm::vec3(q);
        }
        const glm::dvec3 g = h * glm::dvec3(p);
        const double len = glm::length(g);
        const glm::dvec3 n = g / len;
        const glm::dmat3 P = glm::dmat3(1.0) - outer(n, n);
        glm::dmat3 H(0.0);
        for (int k = 0; k < 3; ++k) H[k][k] = h[k];
        a.normal.push_back(n);
        a.shape.push_back(P * H * P / len);
        a.weight.push_back(1.0f);
        a.dcurv.push_back(implicit_dcurv(n, len, H, [](const glm::dvec3&, const glm::dvec3&, const glm::dvec3&) {
            return 0.0;
        }));
    }
    return a;
}

// z = f(x, y), a random cubic with coefficients uniform in [-amplitude,
// amplitude], sampled on an n x n grid over [-1, 1]^2 whose interior points
// are jittered by up to `jitter` cells (Gaussian-free, deterministic for a
// seed). Normal up (+z); with X_x, X_y the tangents, G the first fundamental
// form and B = -Hess f / W (W = |(-fx, -fy, 1)|), S = J G^-1 B G^-1 J^T,
// J = [X_x X_y]. Vertices with max(|x|, |y|) > `window` get weight 0.
inline AnalyticMesh analytic_cubic_patch(int n, double amplitude, double jitter, double window, uint32_t seed) {
    std::mt19937 rng(seed);
    auto uniform = [&] { return double(rng()) / 4294967295.0 * 2.0 - 1.0; };  // [-1, 1]
    double c[10];
    for (double& x : c) x = amplitude * uniform();
    AnalyticMesh a;
    const double h = 2.0 / n;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            double x = -1 + j * h, y = -1 + i * h;
            const double jx = uniform(), jy = uniform();
            if (i > 0 && i < n && j > 0 && j < n) {
                x += jitter * h * jx;
                y += jitter * h * jy;
            }
            const double f = c[0] + c[1] * x + c[2] * y + c[3] * x * x + c[4] * x * y + c[5] * y * y +
                             c[6] * x * x * x + c[7] * x * x * y + c[8] * x * y * y + c[9] * y * y * y;
            const double fx = c[1] + 2 * c[3] * x + c[4] * y + 3 * c[6] * x * x + 2 * c[7] * x * y + c[8] * y * y;
            const double fy = c[2] + c[4] * x + 2 * c[5] * y + c[7] * x * x + 2 * c[8] * x * y + 3 * c[9] * y * y;
            const double fxx = 2 * c[3] + 6 * c[6] * x + 2 * c[7] * y;
            const double fxy = c[4] + 2 * c[7] * x + 2 * c[8] * y;
            const double fyy = 2 * c[5] + 2 * c[8] * x + 6 * c[9] * y;
            a.mesh.positions.push_back(glm::vec3(float(x), float(y), float(f)));
            const double W = std::sqrt(1 + fx * fx + fy * fy);
            a.normal.push_back(glm::dvec3(-fx, -fy, 1) / W);
            const glm::dvec3 Xx(1, 0, fx), Xy(0, 1, fy);
            // 2x2 algebra written out: Gi = G^-1, M = Gi B Gi.
            const double g11 = 1 + fx * fx, g12 = fx * fy, g22 = 1 + fy * fy, det = g11 * g22 - g12 * g12;
            const double i11 = g22 / det, i12 = -g12 / det, i22 = g11 / det;
            const double b11 = -fxx / W, b12 = -fxy / W, b22 = -fyy / W;
            const double t11 = i11 * b11 + i12 * b12, t12 = i11 * b12 + i12 * b22;  // Gi B
            const double t21 = i12 * b11 + i22 * b12, t22 = i12 * b12 + i22 * b22;
            const double m11 = t11 * i11 + t12 * i12, m12 = t11 * i12 + t12 * i22;
            const double m22 = t21 * i12 + t22 * i22;
            a.shape.push_back(m11 * outer(Xx, Xx) + m12 * (outer(Xx, Xy) + outer(Xy, Xx)) + m22 * outer(Xy, Xy));
            // C: F = z - f(x, y), so H = -Hess f and T = -(third derivatives of f).
            glm::dmat3 H(0.0);
            H[0][0] = -fxx;
            H[0][1] = H[1][0] = -fxy;
            H[1][1] = -fyy;
            const double f3[4] = {6 * c[6], 2 * c[7], 2 * c[8], 6 * c[9]};  // by the number of y's
            a.dcurv.push_back(implicit_dcurv(a.normal.back(), W, H,
                                             [&](const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r) {
                                                 double t = 0;
                                                 for (int i = 0; i < 2; ++i)
                                                     for (int j = 0; j < 2; ++j)
                                                         for (int k = 0; k < 2; ++k)
                                                             t -= f3[i + j + k] * p[i] * q[j] * r[k];
                                                 return t;
                                             }));
            a.weight.push_back(std::max(std::fabs(x), std::fabs(y)) <= window ? 1.0f : 0.0f);
        }
    auto idx = [&](int i, int j) { return uint32_t(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            a.mesh.faces.push_back({idx(i, j), idx(i, j + 1), idx(i + 1, j + 1)});
            a.mesh.faces.push_back({idx(i, j), idx(i + 1, j + 1), idx(i + 1, j)});
        }
    return a;
}

// Gaussian noise of standard deviation eta times the median edge length,
// along the true normal (the paper's Fig. 8 noise); the truth is kept, so
// errors are measured against the clean surface.
inline AnalyticMesh with_normal_noise(AnalyticMesh a, double eta, uint32_t seed) {
    const double h = edge_length_stats(a.mesh, build_edge_table(a.mesh)).median;
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss(0.0, eta * h);
    for (size_t i = 0; i < a.mesh.positions.size(); ++i)
        a.mesh.positions[i] += glm::vec3(float(gauss(rng)) * glm::vec3(a.normal[i]));
    return a;
}

// Mean over directions of the squared normal curvature of a symmetric 2x2 tensor.
inline double mean_square_over_directions(double e11, double e12, double e22) {
    return (3 * e11 * e11 + 3 * e22 * e22 + 2 * e11 * e22 + 4 * e12 * e12) / 8;
}

// The relative RMS normal-curvature error of `fields` (estimated on a mesh
// with the same vertices as `truth`, possibly displaced by noise).
inline double relative_curvature_error(const SurfaceFields& fields, const AnalyticMesh& truth) {
    double err = 0, ref = 0;
    for (size_t i = 0; i < truth.shape.size(); ++i) {
        if (truth.weight[i] == 0) continue;
        glm::vec3 fu, fv;
        tangent_frame(glm::vec3(truth.normal[i]), fu, fv);
        const glm::dvec3 u(fu), v(fv), d1(fields.d1[i]), d2(fields.d2[i]);
        const glm::dmat3& S = truth.shape[i];
        const glm::dmat3 E = double(fields.k1[i]) * outer(d1, d1) + double(fields.k2[i]) * outer(d2, d2);
        auto form = [](const glm::dmat3& M, const glm::dvec3& a, const glm::dvec3& b) { return glm::dot(a, M * b); };
        const double t11 = form(S, u, u), t12 = form(S, u, v), t22 = form(S, v, v);
        const double e11 = form(E, u, u) - t11, e12 = form(E, u, v) - t12, e22 = form(E, v, v) - t22;
        err += truth.weight[i] * mean_square_over_directions(e11, e12, e22);
        ref += truth.weight[i] * mean_square_over_directions(t11, t12, t22);
    }
    return ref > 0 ? std::sqrt(err / ref) : 0.0;
}

// |C|^2 = a^2 + 3 b^2 + 3 c^2 + d^2: the squared Frobenius norm of the
// symmetric 3-tensor C = (a, b, c, d).
inline double dcurv_norm2(const glm::dvec4& C) { return C[0] * C[0] + 3 * C[1] * C[1] + 3 * C[2] * C[2] + C[3] * C[3]; }

// The denominator of the relative C error, squared (a sum over vertices, as
// the error's): the true |C|^2; where C is zero everywhere (a sphere) the
// square of the mean squared normal curvature instead (the same units,
// 1 / length^4: on a sphere of radius r the error is then RMS |C error| r^2).
inline double dcurv_reference2(const AnalyticMesh& truth) {
    double c2 = 0, k4 = 0;
    for (size_t i = 0; i < truth.dcurv.size(); ++i) {
        if (truth.weight[i] == 0) continue;
        glm::vec3 fu, fv;
        tangent_frame(glm::vec3(truth.normal[i]), fu, fv);
        const glm::dvec3 u(fu), v(fv);
        const glm::dmat3& S = truth.shape[i];
        const double k2 = mean_square_over_directions(glm::dot(u, S * u), glm::dot(u, S * v), glm::dot(v, S * v));
        c2 += truth.weight[i] * dcurv_norm2(truth.dcurv[i]);
        k4 += truth.weight[i] * k2 * k2;
    }
    return c2 > 1e-12 * k4 ? c2 : k4;
}

// The relative error of C (in (d1, d2), conventions.md) against `truth`:
// the norm |C| of the error tensor, RMS over vertices, divided by the RMS
// of the true |C| (dcurv_reference2). Compared in the true normal's tangent frame.
inline double relative_dcurv_error(const SurfaceFields& fields, const AnalyticMesh& truth) {
    double err = 0;
    for (size_t i = 0; i < truth.dcurv.size(); ++i) {
        if (truth.weight[i] == 0) continue;
        const glm::dvec4 est = dcurv_in_tangent_frame(glm::dvec4(fields.dcurv[i]), glm::dvec3(fields.d1[i]),
                                                      glm::dvec3(fields.d2[i]), truth.normal[i]);
        err += truth.weight[i] * dcurv_norm2(est - truth.dcurv[i]);
    }
    const double ref = dcurv_reference2(truth);
    return ref > 0 ? std::sqrt(err / ref) : 0.0;
}

}  // namespace kappa::test
