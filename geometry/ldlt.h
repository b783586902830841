// Solves the small symmetric positive-definite systems of the per-face
// least-squares fits (Rusinkiewicz 2004, sec. 3.2 and 3.4) by an LDL^T
// factorisation, in double precision. Those normal equations are
// tridiagonal (3x3 for curvature, 4x4 for its derivative), and LDL^T of a
// tridiagonal matrix has no fill-in: L is unit lower bidiagonal.
#pragma once

#include <cmath>

namespace kappa {

// A = tridiag(off, diag, off): diag[0..N) on the diagonal, off[i] at
// (i, i+1) and (i+1, i). Returns false, leaving x untouched, when A is not
// (numerically) positive definite: a pivot not above `rel_tol` times the
// largest diagonal entry, or non-finite input.
template <int N>
bool ldlt_solve_tridiagonal(const double (&diag)[N], const double (&off)[N - 1], const double (&rhs)[N],
                            double (&x)[N], double rel_tol = 1e-12) {
    double scale = 0;
    for (int i = 0; i < N; ++i) scale = diag[i] > scale ? diag[i] : scale;  // SPD: the diagonal is positive
    if (!(scale > 0 && scale < INFINITY)) return false;
    double d[N], l[N], y[N];  // pivots, sub-diagonal of L (l[i] at (i, i-1)), L y = rhs
    d[0] = diag[0];
    y[0] = rhs[0];
    l[0] = 0;
    if (!(d[0] > rel_tol * scale)) return false;
    for (int i = 1; i < N; ++i) {
        l[i] = off[i - 1] / d[i - 1];
        d[i] = diag[i] - l[i] * off[i - 1];
        if (!(d[i] > rel_tol * scale)) return false;
        y[i] = rhs[i] - l[i] * y[i - 1];
    }
    double z[N];  // D L^T z = y
    z[N - 1] = y[N - 1] / d[N - 1];
    for (int i = N - 2; i >= 0; --i) z[i] = y[i] / d[i] - l[i + 1] * z[i + 1];
    for (int i = 0; i < N; ++i)
        if (!(std::fabs(z[i]) < INFINITY)) return false;
    for (int i = 0; i < N; ++i) x[i] = z[i];
    return true;
}

}  // namespace kappa
