// The LDL^T solver behind the per-face fits, on non-diagonal systems; the
// nested least-squares fits behind the jet and the noise level.
#include "geometry/curvature/ldlt.h"
#include "geometry/curvature/normal_equations.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace kappa;

namespace {

// Dense Gaussian elimination with partial pivoting: an independent reference.
template <int N>
void dense_solve(double (&A)[N][N], double (&b)[N], double (&x)[N]) {
    for (int k = 0; k < N; ++k) {
        int p = k;
        for (int i = k + 1; i < N; ++i)
            if (std::fabs(A[i][k]) > std::fabs(A[p][k])) p = i;
        for (int j = 0; j < N; ++j) std::swap(A[k][j], A[p][j]);
        std::swap(b[k], b[p]);
        for (int i = k + 1; i < N; ++i) {
            const double f = A[i][k] / A[k][k];
            for (int j = k; j < N; ++j) A[i][j] -= f * A[k][j];
            b[i] -= f * b[k];
        }
    }
    for (int i = N - 1; i >= 0; --i) {
        double s = b[i];
        for (int j = i + 1; j < N; ++j) s -= A[i][j] * x[j];
        x[i] = s / A[i][i];
    }
}

// Random SPD tridiagonal systems with strong off-diagonals.
template <int N>
void check_random_systems() {
    std::mt19937 rng(7 + N);
    std::uniform_real_distribution<double> u(-1, 1), pos(0.2, 2);
    int checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        double diag[N], off[N - 1], rhs[N], x[N], A[N][N] = {}, b[N], ref[N];
        for (int i = 0; i < N; ++i) diag[i] = pos(rng);
        for (int i = 0; i + 1 < N; ++i) off[i] = u(rng) * std::sqrt(diag[i] * diag[i + 1]) * 0.45;  // Gershgorin: stays SPD
        for (int i = 0; i < N; ++i) rhs[i] = 10 * u(rng);
        for (int i = 0; i < N; ++i) {
            A[i][i] = diag[i];
            if (i + 1 < N) A[i][i + 1] = A[i + 1][i] = off[i];
            b[i] = rhs[i];
        }
        REQUIRE(ldlt_solve_tridiagonal<N>(diag, off, rhs, x));
        dense_solve<N>(A, b, ref);
        for (int i = 0; i < N; ++i) REQUIRE(x[i] == Approx(ref[i]).epsilon(1e-9).margin(1e-9));
        ++checked;
    }
    CHECK(checked == 2000);
}

}  // namespace

TEST_CASE("ldlt_solve_tridiagonal agrees with dense elimination on 3x3 and 4x4 systems", "[solver]") {
    check_random_systems<3>();
    check_random_systems<4>();
}

TEST_CASE("ldlt_solve_tridiagonal solves the curvature normal equations exactly", "[solver]") {
    // One face's system [[uu, uv, 0], [uv, uu+vv, uv], [0, uv, vv]] with a strong coupling: a shortcut
    // that drops the (1,2) coupling gets this wrong by several percent.
    const double uu = 2.0, uv = 0.9, vv = 1.1;
    const double diag[3] = {uu, uu + vv, vv}, off[2] = {uv, uv};
    const double x_true[3] = {1.0, -0.5, 0.25};
    const double b[3] = {uu * x_true[0] + uv * x_true[1], uv * x_true[0] + (uu + vv) * x_true[1] + uv * x_true[2],
                         uv * x_true[1] + vv * x_true[2]};
    double x[3];
    REQUIRE(ldlt_solve_tridiagonal<3>(diag, off, b, x));
    for (int i = 0; i < 3; ++i) CHECK(x[i] == Approx(x_true[i]).epsilon(1e-12));
}

TEST_CASE("ldlt_solve_tridiagonal refuses singular and non-finite systems", "[solver]") {
    const double b[3] = {1, 2, 3};
    double x[3] = {42, 42, 42};
    const double sd[3] = {1, 1, 1}, so[2] = {1, 0};  // rows 0 and 1 equal: singular
    CHECK_FALSE(ldlt_solve_tridiagonal<3>(sd, so, b, x));
    const double zd[3] = {0, 0, 0}, zo[2] = {0, 0};
    CHECK_FALSE(ldlt_solve_tridiagonal<3>(zd, zo, b, x));
    const double nd[3] = {NAN, 1, 1}, no[2] = {0, 0};
    CHECK_FALSE(ldlt_solve_tridiagonal<3>(nd, no, b, x));
    const double indefinite[3] = {1, -1, 1}, io[2] = {0, 0};
    CHECK_FALSE(ldlt_solve_tridiagonal<3>(indefinite, io, b, x));
    CHECK(x[0] == 42);  // untouched on failure
}

namespace {

// Monomials up to degree 5 ordered by degree (as the jet's): the leading 6,
// 10, 15 and 21 are the models of degree 2 to 5.
void monomials5(double x, double y, double (&m)[21]) {
    int k = 0;
    for (int d = 0; d <= 5; ++d)
        for (int j = 0; j <= d; ++j) m[k++] = std::pow(x, d - j) * std::pow(y, j);
}

}  // namespace

TEST_CASE("NestedFits gives every leading model from one factor: solutions, residuals, variances", "[solver]") {
    // Random rings of points with random heights: each leading model against
    // dense elimination on its own block of A^T A, its residual against the
    // residuals summed point by point, its variance factors against the
    // inverse's diagonal (columns of the inverse by dense elimination).
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 50; ++trial) {
        const int n = 25 + trial % 20;
        std::vector<std::array<double, 21>> rows(size_t(n), std::array<double, 21>{});
        std::vector<double> z(static_cast<size_t>(n));
        NormalEquations<21> eq;
        double ata[21][21] = {};
        for (int p = 0; p < n; ++p) {
            double m[21];
            monomials5(u(rng), u(rng), m);
            z[size_t(p)] = u(rng);
            std::copy(m, m + 21, rows[size_t(p)].begin());
            eq.add(m, z[size_t(p)]);
            for (int i = 0; i < 21; ++i)
                for (int j = 0; j < 21; ++j) ata[i][j] += m[i] * m[j];
        }
        NestedFits<21> fits([&](int i, int j) { return ata[i][j]; }, 21);
        REQUIRE(fits.rank() == 21);
        double atb[21] = {};
        for (int p = 0; p < n; ++p)
            for (int i = 0; i < 21; ++i) atb[i] += rows[size_t(p)][size_t(i)] * z[size_t(p)];
        double btb = 0;
        for (double h : z) btb += h * h;
        fits.set_rhs(atb, btb);
        const int terms[3] = {3, 4, 5};
        double variance[3][22];
        fits.variances(terms, 21, variance);
        for (int k : {6, 10, 15, 21}) {
            INFO("trial " << trial << ", " << k << " unknowns");
            double x[21];
            REQUIRE(fits.solve(k, x));
            double block[21][21] = {}, b[21] = {}, ref[21] = {};
            const auto load = [&](int rhs) {  // the k x k block and A^T z, or column `rhs` of the identity
                for (int i = 0; i < k; ++i) {
                    for (int j = 0; j < k; ++j) block[i][j] = ata[i][j];
                    b[i] = rhs < 0 ? atb[i] : i == rhs ? 1.0 : 0.0;
                }
                for (int i = k; i < 21; ++i) {  // identity past the block, so dense_solve<21> solves the block
                    for (int j = 0; j < 21; ++j) block[i][j] = block[j][i] = i == j ? 1.0 : 0.0;
                    b[i] = 0;
                }
            };
            load(-1);
            dense_solve<21>(block, b, ref);
            for (int i = 0; i < 21; ++i) CHECK(x[i] == Approx(ref[i]).epsilon(1e-7).margin(1e-7));
            double rss = 0;
            for (int p = 0; p < n; ++p) {
                double r = z[size_t(p)];
                for (int i = 0; i < k; ++i) r -= rows[size_t(p)][size_t(i)] * x[i];
                rss += r * r;
            }
            CHECK(fits.residual(k) == Approx(rss).epsilon(1e-7).margin(1e-12));
            for (int t = 0; t < 3; ++t) {
                load(terms[t]);
                dense_solve<21>(block, b, ref);
                CHECK(variance[t][k] == Approx(ref[terms[t]]).epsilon(1e-7));
            }
            // NormalEquations::solve of the same block: the same bits.
            double y[21];
            REQUIRE(eq.solve(k, y));
            for (int i = 0; i < 21; ++i) CHECK(y[i] == x[i]);
        }
    }
}

TEST_CASE("NestedFits stops its rank at the first model the points do not determine", "[solver]") {
    // Points on the line y = x: 1, x, y are dependent (rank 2), so only the
    // constant and x are fitted; a non-finite entry stops the rank there too.
    double ata[6][6] = {};
    for (int p = 0; p < 30; ++p) {
        const double t = -1 + p / 15.0, m[6] = {1, t, t, t * t, t * t, t * t};
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) ata[i][j] += m[i] * m[j];
    }
    NestedFits<6> fits([&](int i, int j) { return ata[i][j]; }, 6);
    CHECK(fits.rank() == 2);
    const double atb[6] = {1, 2, 3, 4, 5, 6};
    fits.set_rhs(atb, 100);
    double x[6];
    CHECK(fits.solve(2, x));
    CHECK(x[2] == 0);
    ata[1][1] = NAN;
    CHECK(NestedFits<6>([&](int i, int j) { return ata[i][j]; }, 6).rank() == 1);
}
