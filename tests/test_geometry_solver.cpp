// The small LDL^T solver behind the per-face fits, on non-diagonal systems.
#include "geometry/ldlt.h"

#include <catch2/catch.hpp>

#include <random>

using namespace kappa;

namespace {

// A = M^T M + diag(shift): symmetric positive definite, dense.
template <int N>
void random_spd(std::mt19937& rng, double (&A)[N][N], double shift) {
    std::uniform_real_distribution<double> u(-1, 1);
    double M[N][N];
    for (auto& row : M)
        for (double& x : row) x = u(rng);
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
            A[i][j] = i == j ? shift : 0.0;
            for (int k = 0; k < N; ++k) A[i][j] += M[k][i] * M[k][j];
        }
}

template <int N>
void check_random_systems() {
    std::mt19937 rng(7 + N);
    std::uniform_real_distribution<double> u(-10, 10);
    for (int trial = 0; trial < 500; ++trial) {
        double A[N][N], b[N], x_true[N], x[N];
        random_spd<N>(rng, A, 0.05);
        for (double& v : x_true) v = u(rng);
        for (int i = 0; i < N; ++i) {
            b[i] = 0;
            for (int j = 0; j < N; ++j) b[i] += A[i][j] * x_true[j];
        }
        REQUIRE(ldlt_solve<N>(A, b, x));
        // Condition numbers here stay below ~1e4, so 1e-9 relative is generous for double.
        for (int i = 0; i < N; ++i) REQUIRE(x[i] == Approx(x_true[i]).margin(1e-9 * 10).epsilon(1e-9));
    }
}

}  // namespace

TEST_CASE("ldlt_solve solves dense 3x3 and 4x4 SPD systems", "[solver]") {
    check_random_systems<3>();
    check_random_systems<4>();
}

TEST_CASE("ldlt_solve handles the curvature normal equations' coupling exactly", "[solver]") {
    // The 3x3 system of a single face: [[uu, uv, 0], [uv, uu+vv, uv], [0, uv, vv]], with a strong
    // off-diagonal. A shortcut that ignores the (1,2) coupling gets this wrong by several percent.
    const double uu = 2.0, uv = 0.9, vv = 1.1;
    const double A[3][3] = {{uu, uv, 0}, {uv, uu + vv, uv}, {0, uv, vv}};
    const double x_true[3] = {1.0, -0.5, 0.25};
    double b[3], x[3];
    for (int i = 0; i < 3; ++i) b[i] = A[i][0] * x_true[0] + A[i][1] * x_true[1] + A[i][2] * x_true[2];
    REQUIRE(ldlt_solve<3>(A, b, x));
    for (int i = 0; i < 3; ++i) CHECK(x[i] == Approx(x_true[i]).epsilon(1e-12));
}

TEST_CASE("ldlt_solve refuses singular and non-finite systems", "[solver]") {
    const double singular[3][3] = {{1, 1, 0}, {1, 1, 0}, {0, 0, 1}};
    const double zero[3][3] = {};
    const double nan_sys[3][3] = {{NAN, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double b[3] = {1, 2, 3};
    double x[3] = {42, 42, 42};
    CHECK_FALSE(ldlt_solve<3>(singular, b, x));
    CHECK_FALSE(ldlt_solve<3>(zero, b, x));
    CHECK_FALSE(ldlt_solve<3>(nan_sys, b, x));
    CHECK(x[0] == 42);  // untouched on failure
}
