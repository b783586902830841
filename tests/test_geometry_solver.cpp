// The LDL^T solver behind the per-face fits, on non-diagonal systems.
#include "geometry/curvature/ldlt.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

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
