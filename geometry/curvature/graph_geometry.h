// Curvature and its derivative of a height function z = f(x, y), at a point
// where f may have a non-zero gradient (p, q), from f's partial derivatives
// up to third order there. Used by the fits (jet.h, points_normals_fit.h)
// to read II and C off the fitted polynomial exactly, without first
// rotating it into Monge form.
//
// With the parametrisation X(x, y) = (x, y, f), W = sqrt(1 + p^2 + q^2) and
// the normal N = (-p, -q, 1) / W (the +z side):
//   first fundamental form  g_ij = delta_ij + f_i f_j,
//   second (II = dN, convex positive, conventions.md)  L_ij = -f_ij / W,
//   Christoffel symbols     Gamma^m_ij = f_m f_ij / W^2,
//   C = covariant derivative of II:
//     C_kij = d_k L_ij - Gamma^m_ki L_mj - Gamma^m_kj L_im,
//     d_k L_ij = -f_ijk / W + f_ij (f_l f_lk) / W^3,
// symmetric in all three indices (Codazzi). A tangent vector t = a X_x + b
// X_y has (a, b) = (t.x, t.y), so II(s, t) = L_ij s_i t_j and
// C(r, s, t) = C_kij r_k s_i t_j (do Carmo, "Differential Geometry of
// Curves and Surfaces", sec. 3-3 and 4-3).
#pragma once

#include <glm/vec3.hpp>

#include <cmath>

namespace kappa {

struct HeightDerivatives {
    double fx = 0, fy = 0;
    double fxx = 0, fxy = 0, fyy = 0;
    double fxxx = 0, fxxy = 0, fxyy = 0, fyyy = 0;
};

// The unit normal (-p, -q, 1) / W in the (x, y, z) frame of the fit.
inline glm::dvec3 graph_normal(const HeightDerivatives& d) {
    return glm::dvec3(-d.fx, -d.fy, 1.0) / std::sqrt(1.0 + d.fx * d.fx + d.fy * d.fy);
}

// II = (II(e1,e1), II(e1,e2), II(e2,e2)) and C = (C(e1,e1,e1), C(e1,e1,e2),
// C(e1,e2,e2), C(e2,e2,e2)) for unit tangents e1, e2 given in the fit's
// (x, y, z) frame (tangent to graph_normal(d)).
inline void graph_curvature(const HeightDerivatives& d, const glm::dvec3& e1, const glm::dvec3& e2, double (&II)[3],
                            double (&C)[4]) {
    const double g[2] = {d.fx, d.fy};
    const double f2[2][2] = {{d.fxx, d.fxy}, {d.fxy, d.fyy}};
    const double f3n[4] = {d.fxxx, d.fxxy, d.fxyy, d.fyyy};  // indexed by the number of y's
    const double W2 = 1.0 + g[0] * g[0] + g[1] * g[1], W = std::sqrt(W2);
    double L[2][2], cov[2][2][2];
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) L[i][j] = -f2[i][j] / W;
    for (int k = 0; k < 2; ++k) {
        const double gk = g[0] * f2[0][k] + g[1] * f2[1][k];  // f_l f_lk
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                double v = -f3n[i + j + k] / W + f2[i][j] * gk / (W * W2);
                for (int m = 0; m < 2; ++m) {
                    v -= g[m] * f2[k][i] / W2 * L[m][j];
                    v -= g[m] * f2[k][j] / W2 * L[i][m];
                }
                cov[k][i][j] = v;
            }
    }
    const double a[2][2] = {{e1.x, e1.y}, {e2.x, e2.y}};
    auto form2 = [&](int s, int t) {
        double r = 0;
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) r += L[i][j] * a[s][i] * a[t][j];
        return r;
    };
    auto form3 = [&](int r, int s, int t) {
        double v = 0;
        for (int k = 0; k < 2; ++k)
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) v += cov[k][i][j] * a[r][k] * a[s][i] * a[t][j];
        return v;
    };
    II[0] = form2(0, 0);
    II[1] = form2(0, 1);
    II[2] = form2(1, 1);
    C[0] = form3(0, 0, 0);
    C[1] = form3(0, 0, 1);
    C[2] = form3(0, 1, 1);
    C[3] = form3(1, 1, 1);
}

}  // namespace kappa
