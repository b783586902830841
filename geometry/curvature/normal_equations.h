// Small dense least-squares problems solved by their normal equations, in
// double: rows are accumulated into A^T A and A^T b, then the system is
// equilibrated (D A^T A D with D = diag^-1/2, so every column has unit norm)
// and solved by Cholesky. The callers centre and scale their coordinates
// first, so the columns are of comparable size and the equilibrated matrix
// is well conditioned wherever the points support the model.
//
// Unknowns ordered by importance (e.g. monomials by degree) make the fits
// nested: the leading m x m block of A^T A is the normal matrix of the
// model with the first m unknowns, and the leading block of a Cholesky
// factor is that block's factor. NestedFits factors once and gives every
// leading model from it (solution, residual, variances), which is how the
// fits compare or drop degrees.
#pragma once

#include "geometry/parallel/double_lanes.h"

#include <algorithm>
#include <cmath>

namespace kappa {

template <int N>
class NormalEquations {
public:
    // Adds the row `a` (N entries) with target value b and weight w.
    void add(const double (&a)[N], double b, double w = 1.0) {
        for (int i = 0; i < N; ++i) {
            const double wa = w * a[i];
            for (int j = i; j < N; ++j) ata_[i][j] += wa * a[j];
            atb_[i] += wa * b;
        }
        btb_ += w * b * b;
    }

    // Solves for the first k unknowns only (the others set to 0). Returns
    // false when the block is not numerically positive definite after
    // equilibration (a pivot below rel_tol), or on non-finite values.
    bool solve(int k, double (&x)[N], double rel_tol = 1e-11) const;

private:
    double ata_[N][N] = {};  // upper triangle used
    double atb_[N] = {};
    double btb_ = 0;
};

// The fits of the leading models of a NormalEquations from one Cholesky
// factorisation U^T U = D A^T A D of its leading k x k block, and the
// forward solve y = U^-T D A^T b: the model with the first m unknowns has
// the solution D U_m^-1 y[0, m) and the residual sum of squares
// b^T b - |y[0, m)|^2 (each more unknown takes its y_i^2 off).
template <int N>
class NestedFits {
public:
    // Factors the leading k x k block of A^T A, given as ata(i, j) for
    // i <= j (a NormalEquations' sums, or a caller's own). set_rhs gives the
    // right-hand side before any fit is read.
    template <typename Ata>
    NestedFits(const Ata& ata, int k, double rel_tol = 1e-11) {
        int limit = k;
        for (int i = 0; i < k; ++i) {
            const double a = ata(i, i);
            if (!(a > 0) || !std::isfinite(a)) {
                limit = i;
                break;
            }
            d_[i] = 1.0 / std::sqrt(a);
        }
        // Entries are written by pairs wherever they are read by pairs (a
        // pair read from two single writes waits for them to reach the cache:
        // 5% of the jet's time). The updates below start up to 3 entries left
        // of the diagonal.
        const auto entry = [&](int j, int i) { return i >= j && i < limit ? ata(j, i) * d_[i] * d_[j] : 0.0; };
        for (int j = 0; j < N; ++j)
            for (int i = std::max(j / 2 * 2 - 2, 0); i < kPadded; i += 2)
                lanes::store_pair(&u_[j][i], lanes::Doubles2{entry(j, i), entry(j, i + 1)});
        // Right-looking: row j of U, then its outer product off the rest of
        // the upper triangle, by pairs of entries to the ends of the rows,
        // up to four rows at a time (entries below the diagonal or past the
        // block take values nothing reads). Every entry of U gets the same
        // operations in the same order as in a column-by-column Cholesky.
        rank_ = limit;
        for (int j = 0; j < limit; ++j) {
            const double pivot = u_[j][j];
            if (!(pivot > rel_tol)) {
                rank_ = j;
                break;
            }
            const double ujj = std::sqrt(pivot);
            const lanes::Doubles2 ujj2{ujj, ujj};
            int i = j + 1;
            if (j % 2 == 0) {  // the pair (j, j + 1): row j + 1's update reads it
                lanes::store_pair(&u_[j][j], lanes::Doubles2{ujj, u_[j][j + 1] / ujj});
                ++i;
            } else {
                u_[j][j] = ujj;
            }
            for (; i < limit; i += 2) lanes::store_pair(&u_[j][i], lanes::load_pair(&u_[j][i]) / ujj2);
            for (int m = j + 1; m < limit;) {  // four or two rows at a time from the start of a pair
                if (N >= 4 && m % 2 == 0 && m + 3 < limit) {  // N >= 4: no rows past the end to warn of
                    subtract_scaled<4>(&u_[m], {u_[j][m], u_[j][m + 1], u_[j][m + 2], u_[j][m + 3]}, u_[j], m);
                    m += 4;
                } else if (m % 2 == 0 && m + 1 < limit) {
                    subtract_scaled<2>(&u_[m], {u_[j][m], u_[j][m + 1]}, u_[j], m);
                    m += 2;
                } else {
                    subtract_scaled<1>(&u_[m], {u_[j][m]}, u_[j], m);
                    ++m;
                }
            }
        }
    }

    // The leading models that are numerically positive definite: 0 to k.
    int rank() const { return rank_; }

    // The right-hand side A^T b and b^T b (again for another one: the same A^T A).
    void set_rhs(const double (&atb)[N], double btb) {
        btb_ = btb;
        double r[kPadded];
        const auto entry = [&](int i) { return i < rank_ ? atb[std::min(i, N - 1)] * d_[std::min(i, N - 1)] : 0.0; };
        for (int i = 0; i < kPadded; i += 2) lanes::store_pair(&r[i], lanes::Doubles2{entry(i), entry(i + 1)});
        forward(0, rank_, r, y_);
    }

    // The model with the first m <= rank() unknowns (the others set to 0);
    // false on non-finite values.
    bool solve(int m, double (&x)[N]) const {
        double z[N];
        for (int i = m - 1; i >= 0; --i) {
            double s = y_[i];
            for (int p = i + 1; p < m; ++p) s -= u_[i][p] * z[p];
            z[i] = s / u_[i][i];
        }
        for (int i = 0; i < m; ++i)
            if (!std::isfinite(z[i])) return false;
        for (int i = 0; i < N; ++i) x[i] = i < m ? z[i] * d_[i] : 0.0;
        return true;
    }

    // The residual sum of squares of the model with the first m <= rank() unknowns.
    double residual(int m) const {
        double r = btb_;
        for (int i = 0; i < m; ++i) r -= y_[i] * y_[i];
        return r > 0 ? r : 0;
    }

    // The variance factors (A^T A)^-1_aa (unit noise on b) of the unknowns
    // a = terms[0] < terms[1] < ... in the models up to the first m <= rank()
    // unknowns: v[c][m'] for unknown terms[c], terms[c] < m' <= m. (A^T A)^-1
    // = D U^-1 U^-T D, so entry aa of model m' is d_a^2 |U^-T e_a|^2 over
    // [a, m') (U^-T e_a is zero above a). All T solves at once (the later
    // ones start with zeros, which leave them as they are).
    template <int T>
    void variances(const int (&terms)[T], int m, double (*v)[N + 1]) const {
        double r[T][kPadded], sum[T] = {};
        for (int c = 0; c < T; ++c)
            for (int i = 0; i < kPadded; i += 2)
                lanes::store_pair(&r[c][i], lanes::Doubles2{i == terms[c] ? 1.0 : 0.0, i + 1 == terms[c] ? 1.0 : 0.0});
        for (int p = terms[0]; p < m; ++p) {
            double z[T];
            for (int c = 0; c < T; ++c) {
                z[c] = r[c][p] / u_[p][p];
                if (p < terms[c]) continue;
                sum[c] += z[c] * z[c];
                v[c][p + 1] = sum[c] * d_[terms[c]] * d_[terms[c]];
            }
            subtract_scaled<T>(r, z, u_[p], p + 1);
        }
    }

private:
    static constexpr int kPadded = (N + 1) / 2 * 2;  // rows of U padded to whole pairs

    // U^T z = r on [first, last) (r zero above first), r overwritten (by
    // pairs, as the factorisation).
    void forward(int first, int last, double (&r)[kPadded], double (&z)[N]) const {
        for (int p = first; p < last; ++p) {
            z[p] = r[p] / u_[p][p];
            subtract_scaled<1>(&r, {z[p]}, u_[p], p + 1);
        }
    }

    // rows[c][i] -= a[c] * other[i] for the R rows, from i = from (the pair
    // that holds it) to the end, by pairs: in each entry the one operation a
    // scalar loop does.
    template <int R>
    static void subtract_scaled(double (*rows)[kPadded], const double (&a)[R], const double (&other)[kPadded],
                                int from) {
        lanes::Doubles2 a2[R];
        for (int c = 0; c < R; ++c) a2[c] = lanes::Doubles2{a[c], a[c]};
        for (int i = from / 2 * 2; i < kPadded; i += 2) {
            const lanes::Doubles2 o = lanes::load_pair(&other[i]);
            for (int c = 0; c < R; ++c) lanes::store_pair(&rows[c][i], lanes::load_pair(&rows[c][i]) - a2[c] * o);
        }
    }

    int rank_ = 0;
    double d_[N];
    alignas(16) double u_[N][kPadded];  // upper triangle: U
    double y_[N];
    double btb_ = 0;
};

template <int N>
bool NormalEquations<N>::solve(int k, double (&x)[N], double rel_tol) const {
    NestedFits<N> fits([this](int i, int j) { return ata_[i][j]; }, k, rel_tol);
    if (fits.rank() < k) return false;
    fits.set_rhs(atb_, btb_);
    return fits.solve(k, x);
}

}  // namespace kappa
