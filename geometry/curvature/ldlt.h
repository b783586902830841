// Solves the small symmetric positive-definite systems of the per-face
// least-squares fits (Rusinkiewicz 2004, sec. 3.2 and 3.4) by an LDL^T
// factorisation, in double precision. Those normal equations are
// tridiagonal (3x3 for curvature, 4x4 for its derivative), and LDL^T of a
// tridiagonal matrix has no fill-in: L is unit lower bidiagonal.
#pragma once

#include "geometry/parallel/double_lanes.h"

#include <cmath>

namespace kappa {

// A = tridiag(off, diag, off): diag[0..N) on the diagonal, off[i] at
// (i, i+1) and (i+1, i), per lane (double_lanes.h). Returns, per lane,
// whether A is (numerically) positive definite and x finite: false where a
// pivot is not above `rel_tol` times the largest diagonal entry, or the
// input is not finite (x is then meaningless).
//
// The pivots come from the leading principal minors (continuant recurrence
// m_k = a_k m_{k-1} - b_{k-1}^2 m_{k-2}, pivot d_k = m_k / m_{k-1}) of A
// scaled by its largest diagonal entry, so the N divisions are independent
// of one another instead of a chain of 2N - 1 (these solves were a seventh
// of the curvature job); after the scaling every minor lies in
// (rel_tol^N, 1], far from overflow and underflow.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"  // see double_lanes.h
template <int N, typename D>
KAPPA_LANES_INLINE lanes::Mask<D> ldlt_solve_tridiagonal_lanes(const D (&diag)[N], const D (&off)[N - 1], const D (&rhs)[N], D (&x)[N],
                                            double rel_tol = 1e-12) {
    using lanes::larger;
    using lanes::magnitude;
    D scale = diag[0];
    for (int i = 1; i < N; ++i) scale = larger<D>(scale, diag[i]);  // SPD: the diagonal is positive
    lanes::Mask<D> ok = (scale > 0.0) & (scale < INFINITY);
    const D s = 1.0 / scale;
    D a[N], b[N], r[N];  // A / scale, rhs / scale (b[i] at (i, i+1))
    for (int i = 0; i < N; ++i) {
        a[i] = diag[i] * s;
        b[i] = i + 1 < N ? off[i] * s : D{};
        r[i] = rhs[i] * s;
    }
    D minor[N];
    minor[0] = a[0];
    ok = ok & (minor[0] > rel_tol);
    for (int k = 1; k < N; ++k) {
        minor[k] = k >= 2 ? a[k] * minor[k - 1] - b[k - 1] * b[k - 1] * minor[k - 2]
                          : a[k] * minor[k - 1] - b[k - 1] * b[k - 1];
        ok = ok & (minor[k] > rel_tol * minor[k - 1]);  // pivot d_k > rel_tol (scaled)
    }
    D inv_d[N];  // 1 / d_k = m_{k-1} / m_k
    inv_d[0] = 1.0 / minor[0];
    for (int k = 1; k < N; ++k) inv_d[k] = minor[k - 1] / minor[k];
    D l[N], y[N];  // sub-diagonal of L (l[i] at (i, i-1)), L y = r
    y[0] = r[0];
    for (int i = 1; i < N; ++i) {
        l[i] = b[i - 1] * inv_d[i - 1];
        y[i] = r[i] - l[i] * y[i - 1];
    }
    x[N - 1] = y[N - 1] * inv_d[N - 1];  // D L^T x = y
    for (int i = N - 2; i >= 0; --i) x[i] = y[i] * inv_d[i] - l[i + 1] * x[i + 1];
    for (int i = 0; i < N; ++i) ok = ok & (magnitude<D>(x[i]) < INFINITY);
    return ok;
}
#pragma GCC diagnostic pop

// The same for one system: false, leaving x untouched, where it fails.
template <int N>
bool ldlt_solve_tridiagonal(const double (&diag)[N], const double (&off)[N - 1], const double (&rhs)[N],
                            double (&x)[N], double rel_tol = 1e-12) {
    double z[N];
    if (!ldlt_solve_tridiagonal_lanes<N, double>(diag, off, rhs, z, rel_tol)) return false;
    for (int i = 0; i < N; ++i) x[i] = z[i];
    return true;
}

}  // namespace kappa
