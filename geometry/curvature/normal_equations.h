// Small dense least-squares problems solved by their normal equations, in
// double: rows are accumulated into A^T A and A^T b, then the system is
// equilibrated (D A^T A D with D = diag^-1/2, so every column has unit norm)
// and solved by Cholesky. The callers centre and scale their coordinates
// first, so the columns are of comparable size and the equilibrated matrix
// is well conditioned wherever the points support the model.
//
// Unknowns ordered by importance (e.g. monomials by degree) allow solving
// the leading k x k block alone: the same accumulation then fits the
// lower-degree model, which is how the fits drop their degree.
#pragma once

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

    // Sets the accumulated sums directly (callers that can form A^T A
    // faster than row by row, from moments): ata upper triangle, atb, b^T b.
    void set(int i, int j, double ata) { ata_[i][j] = ata; }
    void set_rhs(int i, double atb) { atb_[i] = atb; }
    void set_btb(double btb) { btb_ = btb; }

    // Solves for the first k unknowns only (the others set to 0). Returns
    // false when the block is not numerically positive definite after
    // equilibration (a pivot below rel_tol), or on non-finite values.
    bool solve(int k, double (&x)[N], double rel_tol = 1e-11) const { return solve(k, x, rel_tol, nullptr, 0, nullptr); }

    // The same, and the diagonal entries (A^T A)^-1_ii of the k x k block for
    // the `count` unknowns index[0..count): their variances for unit noise on b.
    bool solve(int k, double (&x)[N], double rel_tol, const int* index, int count, double* variance) const {
        double d[N], l[N][N];
        if (!factor(k, rel_tol, d, l)) return false;
        double y[N];
        for (int i = 0; i < k; ++i) {
            double s = atb_[i] * d[i];
            for (int p = 0; p < i; ++p) s -= l[i][p] * y[p];
            y[i] = s / l[i][i];
        }
        for (int i = k - 1; i >= 0; --i) {
            double s = y[i];
            for (int p = i + 1; p < k; ++p) s -= l[p][i] * y[p];
            y[i] = s / l[i][i];
        }
        for (int i = 0; i < k; ++i)
            if (!std::isfinite(y[i])) return false;
        for (int i = 0; i < N; ++i) x[i] = i < k ? y[i] * d[i] : 0.0;
        // (A^T A)^-1 = D (L L^T)^-1 D, so entry ii is d_i^2 |L^-1 e_i|^2.
        for (int c = 0; c < count; ++c) {
            const int a = index[c];
            double sum = 0;
            for (int i = a; i < k; ++i) {  // L^-1 e_a is zero above a
                double s = i == a ? 1.0 : 0.0;
                for (int p = a; p < i; ++p) s -= l[i][p] * y[p];
                y[i] = s / l[i][i];
                sum += y[i] * y[i];
            }
            variance[c] = sum * d[a] * d[a];
        }
        return true;
    }

    // The residual sum of squares of solution x (first k unknowns):
    // b^T b - 2 x^T A^T b + x^T A^T A x.
    double residual(const double (&x)[N], int k) const {
        double r = btb_;
        for (int i = 0; i < k; ++i) {
            r -= 2 * x[i] * atb_[i];
            for (int j = 0; j < k; ++j) r += x[i] * x[j] * (i <= j ? ata_[i][j] : ata_[j][i]);
        }
        return r > 0 ? r : 0;
    }

private:
    // Cholesky L L^T of D A^T A D (first k unknowns), D = diag^-1/2.
    bool factor(int k, double rel_tol, double (&d)[N], double (&l)[N][N]) const {
        for (int i = 0; i < k; ++i) {
            if (!(ata_[i][i] > 0) || !std::isfinite(ata_[i][i])) return false;
            d[i] = 1.0 / std::sqrt(ata_[i][i]);
        }
        for (int j = 0; j < k; ++j) {  // column by column
            double s = ata_[j][j] * d[j] * d[j];
            for (int p = 0; p < j; ++p) s -= l[j][p] * l[j][p];
            if (!(s > rel_tol)) return false;
            l[j][j] = std::sqrt(s);
            for (int i = j + 1; i < k; ++i) {
                double t = ata_[j][i] * d[i] * d[j];
                for (int p = 0; p < j; ++p) t -= l[i][p] * l[j][p];
                l[i][j] = t / l[j][j];
            }
        }
        return true;
    }

    double ata_[N][N] = {};  // upper triangle used
    double atb_[N] = {};
    double btb_ = 0;
};

}  // namespace kappa
