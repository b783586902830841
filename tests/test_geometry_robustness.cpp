// Degenerate input is normal input: finite output everywhere, and flags that say where.
#include "geometry/curvature/feature_size.h"
#include "geometry/parallel/parallel.h"
#include "geometry/mesh/primitives.h"
#include "geometry/surface_analysis.h"
#include "geometry/curvature/vertex_flags.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <random>

using namespace kappa;

namespace {

void require_all_finite(const SurfaceFields& s) {
    for (size_t i = 0; i < s.size(); ++i) {
        INFO("vertex " << i);
        for (int c = 0; c < 3; ++c) {
            REQUIRE(std::isfinite(s.normals[i][c]));
            REQUIRE(std::isfinite(s.d1[i][c]));
            REQUIRE(std::isfinite(s.d2[i][c]));
        }
        for (int c = 0; c < 4; ++c) REQUIRE(std::isfinite(s.dcurv[i][c]));
        REQUIRE(std::isfinite(s.k1[i]));
        REQUIRE(std::isfinite(s.k2[i]));
        REQUIRE(std::isfinite(s.point_areas[i]));
        REQUIRE(glm::length(s.normals[i]) == Approx(1.0f).epsilon(1e-5));
    }
}

// Per-vertex invariants of conventions.md: k1 >= k2, d1, d2 unit, tangent, d1 x d2 = n.
void require_frame_invariants(const SurfaceFields& s) {
    for (size_t i = 0; i < s.size(); ++i) {
        INFO("vertex " << i);
        REQUIRE(s.k1[i] >= s.k2[i]);
        REQUIRE(glm::length(s.d1[i]) == Approx(1.0f).epsilon(1e-4));
        REQUIRE(glm::length(s.d2[i]) == Approx(1.0f).epsilon(1e-4));
        REQUIRE(std::fabs(glm::dot(s.d1[i], s.normals[i])) < 1e-4f);
        REQUIRE(glm::length(glm::cross(s.d1[i], s.d2[i]) - s.normals[i]) < 1e-4f);
    }
}

// Smoothing options with every estimator (geometry/curvature/estimator.h):
// each must pass what the default passes.
std::vector<SmoothingOptions> with_each_estimator(SmoothingOptions o = {}) {
    std::vector<SmoothingOptions> out;
    for (const std::string& name : estimator_names()) {
        o.estimator = *parse_estimator(name);
        out.push_back(o);
    }
    return out;
}

}  // namespace

TEST_CASE("Principal frames obey the conventions on curved meshes", "[robustness]") {
    for (const Mesh& m : {make_torus(1.0f, 0.35f, 48, 20), make_ellipsoid(1.5f, 1.0f, 0.6f, 4),
                          make_jittered_sphere(1.0f, 3, 0.9f, 5)})
        for (const SmoothingOptions& o : with_each_estimator()) {
            INFO(estimator_name(o.estimator));
            const SurfaceFields s = compute_surface_fields(m, o);
            require_all_finite(s);
            require_frame_invariants(s);
        }
}

TEST_CASE("Degenerate faces, isolated vertices, non-manifold edges and holes stay finite and are flagged",
          "[robustness]") {
    Mesh m = make_grid(2.0f, 8);  // 81 vertices, open boundary
    const uint32_t nv = uint32_t(m.positions.size());
    // Collinear triangle on three new points, and a zero-area face with a repeated index.
    m.positions.push_back({0, 0, 1});
    m.positions.push_back({1, 0, 1});
    m.positions.push_back({2, 0, 1});
    m.faces.push_back({nv, nv + 1, nv + 2});
    m.faces.push_back({40, 40, 41});
    // Coincident vertices: a face whose two corners are at the same place.
    m.positions.push_back(m.positions[10]);
    m.faces.push_back({10, nv + 3, 11});
    // An isolated vertex.
    m.positions.push_back({5, 5, 5});
    const uint32_t isolated = nv + 4;
    // A fin: a third face on the interior edge (30, 31).
    m.positions.push_back({0.1f, 0.1f, 0.7f});
    m.faces.push_back({30, 31, nv + 5});

    for (const SmoothingOptions& o : with_each_estimator({0.3f, 0.3f, 0.3f})) {
        INFO(estimator_name(o.estimator) << ", smoothed");
        require_all_finite(compute_surface_fields(m, o));
    }
    for (const SmoothingOptions& o : with_each_estimator()) {
        INFO(estimator_name(o.estimator));
        const SurfaceFields s = compute_surface_fields(m, o);
        require_all_finite(s);
        CHECK(s.flags[isolated] & kFlagIsolated);
        CHECK(s.flags[nv] & kFlagDegenerate);  // only used by the collinear face
        CHECK(s.flags[nv + 1] & kFlagDegenerate);
        CHECK(s.flags[30] & kFlagNonManifold);
        CHECK(s.flags[31] & kFlagNonManifold);
        CHECK(s.flags[0] & kFlagBoundary);  // grid corner
        CHECK(s.flags[70] == 0);           // interior vertex away from the damage
        CHECK(s.k1[70] == Approx(0.0f).margin(1e-6));  // a plane has no curvature
        CHECK(s.k2[70] == Approx(0.0f).margin(1e-6));
        CHECK(std::isfinite(feature_size(m, s)));
    }
}

TEST_CASE("Random garbage meshes never produce NaN or inf", "[robustness]") {
    std::mt19937 rng(123);
    for (int trial = 0; trial < 20; ++trial) {
        Mesh m;
        std::uniform_int_distribution<int> coord(-3, 3);  // small lattice: many coincident/collinear points
        const int nv = 30, nf = 60;
        for (int i = 0; i < nv; ++i) m.positions.push_back(glm::vec3(coord(rng), coord(rng), coord(rng)) * 0.5f);
        std::uniform_int_distribution<uint32_t> vid(0, nv - 1);
        for (int i = 0; i < nf; ++i) m.faces.push_back({vid(rng), vid(rng), vid(rng)});
        for (const SmoothingOptions& o : with_each_estimator({trial % 2 ? 0.5f : 0.0f, 0.4f, 0.4f})) {
            INFO(estimator_name(o.estimator) << ", trial " << trial);
            const SurfaceFields s = compute_surface_fields(m, o);
            require_all_finite(s);
            CHECK(std::isfinite(feature_size(m, s)));
        }
    }
    // Empty mesh and vertices without faces.
    for (const SmoothingOptions& o : with_each_estimator()) {
        INFO(estimator_name(o.estimator));
        Mesh empty;
        CHECK(compute_surface_fields(empty, o).size() == 0);
        Mesh points;
        points.positions = {{0, 0, 0}, {1, 2, 3}};
        const SurfaceFields s = compute_surface_fields(points, o);
        require_all_finite(s);
        CHECK((s.flags[0] & kFlagIsolated));
    }
}

namespace {

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

}  // namespace

TEST_CASE("Results are bit-identical whatever the thread count", "[determinism]") {
    const Mesh m = make_jittered_sphere(1.0f, 6, 0.9f, 9);  // 40k vertices: several chunks per thread
    // The smoothing stages are shared: with the default estimator only (each run costs a second).
    for (SmoothingOptions smooth : with_each_estimator()) {
        if (smooth.estimator == Estimator::rusinkiewicz) smooth = {0.02f, 0.03f, 0.03f};
        INFO(estimator_name(smooth.estimator));
        set_thread_count(1);
        const SurfaceFields one = compute_surface_fields(m, smooth);
        set_thread_count(2);
        const SurfaceFields two = compute_surface_fields(m, smooth);
        set_thread_count(5);
        const SurfaceFields five = compute_surface_fields(m, smooth);
        set_thread_count(0);
        for (const SurfaceFields* other : {&two, &five}) {
            CHECK(same_bits(one.normals, other->normals));
            CHECK(same_bits(one.k1, other->k1));
            CHECK(same_bits(one.k2, other->k2));
            CHECK(same_bits(one.d1, other->d1));
            CHECK(same_bits(one.d2, other->d2));
            CHECK(same_bits(one.dcurv, other->dcurv));
            CHECK(same_bits(one.flags, other->flags));
        }
    }
}
