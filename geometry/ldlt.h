// Solves small symmetric positive-definite systems A x = b by an LDL^T
// factorisation (Golub & Van Loan, Alg. 4.1.2), in double precision.
// Used for the per-face least-squares fits of Rusinkiewicz 2004, sec. 3.2
// (3x3 for curvature, 4x4 for its derivative).
#pragma once

#include <cmath>

namespace kappa {

// Returns false, leaving x untouched, when A is not (numerically) positive
// definite: a pivot below `rel_tol` times the largest diagonal entry.
template <int N>
bool ldlt_solve(const double (&A)[N][N], const double (&b)[N], double (&x)[N], double rel_tol = 1e-12) {
    double L[N][N] = {};
    double d[N];
    double scale = 0;
    for (int i = 0; i < N; ++i) scale = std::fmax(scale, std::fabs(A[i][i]));
    if (!(scale > 0) || !std::isfinite(scale)) return false;
    for (int j = 0; j < N; ++j) {
        double dj = A[j][j];
        for (int k = 0; k < j; ++k) dj -= L[j][k] * L[j][k] * d[k];
        if (!(dj > rel_tol * scale)) return false;
        d[j] = dj;
        L[j][j] = 1;
        for (int i = j + 1; i < N; ++i) {
            double s = A[i][j];
            for (int k = 0; k < j; ++k) s -= L[i][k] * L[j][k] * d[k];
            L[i][j] = s / dj;
        }
    }
    double y[N];
    for (int i = 0; i < N; ++i) {  // L y = b
        double s = b[i];
        for (int k = 0; k < i; ++k) s -= L[i][k] * y[k];
        y[i] = s;
    }
    double z[N];
    for (int i = N - 1; i >= 0; --i) {  // D L^T z = y
        double s = y[i] / d[i];
        for (int k = i + 1; k < N; ++k) s -= L[k][i] * z[k];
        z[i] = s;
    }
    for (int i = 0; i < N; ++i) x[i] = z[i];
    return true;
}

}  // namespace kappa
