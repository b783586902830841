// Curvature, normals and areas against analytic surfaces.
#include "geometry/curvature/curvature.h"
#include "geometry/curvature/vertex_basics.h"
#include "geometry/mesh/primitives.h"
#include "geometry/surface_analysis.h"
#include "geometry/curvature/vertex_flags.h"
#include "geometry/curvature/face_geometry.h"
#include "geometry/curvature/voronoi_areas.h"
#include "geometry/io/mesh_io.h"
#include "geometry/parallel/double_lanes.h"
#include "geometry/parallel/parallel.h"
#include "test_support.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cstring>

#include <algorithm>
#include <cmath>

using namespace kappa;

namespace {

struct ErrorStats {
    double max = 0, rms = 0;
};

template <typename F>
ErrorStats error_over_vertices(size_t n, F err) {
    ErrorStats s;
    for (size_t i = 0; i < n; ++i) {
        const double e = std::fabs(err(i));
        s.max = std::max(s.max, e);
        s.rms += e * e;
    }
    s.rms = std::sqrt(s.rms / double(std::max<size_t>(n, 1)));
    return s;
}

double mean_edge(const Mesh& m) {
    double sum = 0;
    for (const Face& f : m.faces)
        for (int j = 0; j < 3; ++j) sum += glm::length(m.positions[f[(j + 1) % 3]] - m.positions[f[j]]);
    return sum / (3.0 * double(m.faces.size()));
}

double min_edge(const Mesh& m) {
    double least = INFINITY;
    for (const Face& f : m.faces)
        for (int j = 0; j < 3; ++j)
            least = std::min(least, double(glm::length(m.positions[f[(j + 1) % 3]] - m.positions[f[j]])));
    return least;
}

double mesh_area(const Mesh& m) {
    double a = 0;
    for (const Face& f : m.faces)
        a += 0.5 * glm::length(glm::cross(glm::dvec3(m.positions[f[1]] - m.positions[f[0]]),
                                          glm::dvec3(m.positions[f[2]] - m.positions[f[0]])));
    return a;
}

// Positions are floats: each is off the sphere by up to ~eps R, so normals (differences over an
// edge h) carry errors ~eps R/h and curvatures (over h again) ~eps (R/h)^2, relative. The
// estimate itself is exact on a sphere; this is the float precision the test allows.
void check_sphere_exact(const Mesh& m, float R) {
    const double eps = 1.2e-7, h = mean_edge(m) / R;
    const double rel_tol = 4 * eps / (h * h);
    SurfaceFields s = compute_surface_fields(m);
    const auto k1 = error_over_vertices(s.size(), [&](size_t i) { return s.k1[i] * R - 1.0; });
    const auto k2 = error_over_vertices(s.size(), [&](size_t i) { return s.k2[i] * R - 1.0; });
    const auto n = error_over_vertices(s.size(), [&](size_t i) {
        return glm::length(s.normals[i] - glm::normalize(m.positions[i]));
    });
    // |C| differentiates the curvature errors once more, over edges as short as the shortest one;
    // it is compared with the curvature scale 1/R^2.
    const auto c = error_over_vertices(s.size(), [&](size_t i) { return glm::length(s.dcurv[i]) * R * R; });
    INFO("tolerance " << rel_tol << ", k1 max rel err " << k1.max << ", k2 " << k2.max << ", normal " << n.max << ", |C| R^2 " << c.max);
    CHECK(k1.max < rel_tol);
    CHECK(k2.max < rel_tol);
    CHECK(n.max < 4 * eps / h);
    CHECK(c.max < 4 * rel_tol * R / min_edge(m));
}

}  // namespace

TEST_CASE("Max's normals are exact on spheres of any tessellation", "[normals]") {
    for (const Mesh& m : {make_icosphere(2.0f, 3), make_uv_sphere(2.0f, 24, 48),
                          make_jittered_sphere(2.0f, 3, 0.9f, 1)}) {
        // Float positions are off the sphere by ~eps R; over edges of length h that tilts
        // normals by ~eps R / h.
        const double R = 2.0, tol = 4 * 1.2e-7 * R / mean_edge(m);
        const auto n = compute_vertex_basics(build_vertex_faces(m), compute_face_geometry(m)).normals;
        for (size_t i = 0; i < m.positions.size(); ++i)
            REQUIRE(glm::length(n[i] - glm::normalize(m.positions[i])) < tol);
    }
}

TEST_CASE("Mixed Voronoi areas partition the surface", "[areas]") {
    for (const Mesh& m : {make_icosphere(1.0f, 3), make_uv_sphere(1.0f, 20, 40),
                          make_jittered_sphere(1.0f, 3, 0.9f, 2), make_torus(1.0f, 0.3f, 40, 16)}) {
        const FaceGeometry faces = compute_face_geometry(m);
        double sum = 0;
        for (size_t f = 0; f < faces.size(); ++f) {
            const glm::vec3 corner = faces.corner_areas(f);
            REQUIRE(corner.x >= 0);
            REQUIRE(corner.y >= 0);
            REQUIRE(corner.z >= 0);
            sum += double(corner.x) + corner.y + corner.z;
        }
        CHECK(sum == Approx(mesh_area(m)).epsilon(1e-6));
    }
}

TEST_CASE("Mixed Voronoi areas follow Meyer's rules on single triangles", "[areas]") {
    Mesh right;  // right angle at corner 0: the circumcentre is the hypotenuse midpoint
    right.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    right.faces = {{0, 1, 2}};
    auto a = compute_face_geometry(right).corner_areas(0);
    // Area 2: Voronoi gives corner 0 the square [0,1]^2 = 1, corners 1 and 2 half of the rest each.
    CHECK(a.x == Approx(1.0));
    CHECK(a.y == Approx(0.5));
    CHECK(a.z == Approx(0.5));

    Mesh obtuse;  // obtuse at corner 2
    obtuse.positions = {{0, 0, 0}, {4, 0, 0}, {2, 0.5f, 0}};
    obtuse.faces = {{0, 1, 2}};
    a = compute_face_geometry(obtuse).corner_areas(0);  // area 1
    CHECK(a.x == Approx(0.25));
    CHECK(a.y == Approx(0.25));
    CHECK(a.z == Approx(0.5));

    Mesh equilateral;
    equilateral.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, std::sqrt(3.0f) / 2, 0}};
    equilateral.faces = {{0, 1, 2}};
    a = compute_face_geometry(equilateral).corner_areas(0);
    CHECK(a.x == Approx(std::sqrt(3.0) / 12).epsilon(1e-6));
    CHECK(a.y == Approx(std::sqrt(3.0) / 12).epsilon(1e-6));
}

TEST_CASE("Spheres of any tessellation give k1 = k2 = 1/R and C = 0", "[curvature][sphere]") {
    // On a sphere Max's normals are exactly p/R, so every face fit is exactly I/R and the
    // estimate is exact up to float rounding (a few ulps times the fits' condition numbers).
    SECTION("icosphere") { check_sphere_exact(make_icosphere(3.0f, 4), 3.0f); }
    SECTION("uv sphere with skinny polar triangles") { check_sphere_exact(make_uv_sphere(0.5f, 60, 120), 0.5f); }
    SECTION("randomly jittered sphere") {
        for (uint32_t seed = 1; seed <= 3; ++seed) check_sphere_exact(make_jittered_sphere(1.5f, 4, 0.9f, seed), 1.5f);
    }
    SECTION("tiny and huge radii") {
        check_sphere_exact(make_icosphere(1e-3f, 3), 1e-3f);
        check_sphere_exact(make_icosphere(1e3f, 3), 1e3f);
    }
}

namespace {

struct TorusErrors {
    double k_max = 0, k_rms = 0, c_rms = 0, dir_max = 0;
};

// Torus with major radius R, minor r: along the tube 1/r, along the big circle cos v / (R + r cos v)
// (conventions.md); |C| = sqrt(3) R |sin v| / (r (R + r cos v)^2).
TorusErrors torus_errors(float R, float r, int nu, int nv) {
    const Mesh m = make_torus(R, r, nu, nv);
    const SurfaceFields s = compute_surface_fields(m);
    TorusErrors e;
    double c_sq = 0, c_ref_sq = 0;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const size_t idx = size_t(i) * nv + j;
            const double v = 2 * glm::pi<double>() * j / nv, u = 2 * glm::pi<double>() * i / nu;
            const double k_tube = 1.0 / r, k_ring = std::cos(v) / (R + r * std::cos(v));
            const double k1 = std::max(k_tube, k_ring), k2 = std::min(k_tube, k_ring);
            const double err = std::max(std::fabs(s.k1[idx] - k1), std::fabs(s.k2[idx] - k2)) * r;
            e.k_max = std::max(e.k_max, err);
            e.k_rms += err * err;
            // d1 (largest curvature 1/r) runs around the tube: perpendicular to the ring direction.
            const glm::dvec3 ring_dir(-std::sin(u), std::cos(u), 0);
            e.dir_max = std::max(e.dir_max, std::fabs(glm::dot(glm::dvec3(s.d1[idx]), ring_dir)));
            const double c_ref = std::sqrt(3.0) * R * std::fabs(std::sin(v)) / (r * std::pow(R + r * std::cos(v), 2));
            const glm::vec4 C = s.dcurv[idx];
            const double c = std::sqrt(C[0] * C[0] + 3 * C[1] * C[1] + 3 * C[2] * C[2] + C[3] * C[3]);
            c_sq += (c - c_ref) * (c - c_ref);
            c_ref_sq += c_ref * c_ref;
        }
    e.k_rms = std::sqrt(e.k_rms / (double(nu) * nv));
    e.c_rms = std::sqrt(c_sq / c_ref_sq);
    return e;
}

}  // namespace

TEST_CASE("Torus curvature and C match the analytic values and converge", "[curvature][torus]") {
    const float R = 1.0f, r = 0.4f;
    const TorusErrors coarse = torus_errors(R, r, 64, 24);
    const TorusErrors fine = torus_errors(R, r, 128, 48);
    const TorusErrors finer = torus_errors(R, r, 256, 96);
    INFO("k err (x r) max/rms: " << coarse.k_max << "/" << coarse.k_rms << " -> " << fine.k_max << "/" << fine.k_rms
                                 << " -> " << finer.k_max << "/" << finer.k_rms);
    INFO("|C| rel rms: " << coarse.c_rms << " -> " << fine.c_rms << " -> " << finer.c_rms);
    INFO("direction err: " << coarse.dir_max << " -> " << fine.dir_max << " -> " << finer.dir_max);
    // The normal-difference fit is second-order accurate on a regular grid: with h the edge
    // length, errors scale like (h/r)^2. At nv = 24, h/r = 2 pi / 24 = 0.26, (h/r)^2 = 0.07.
    CHECK(coarse.k_max < 0.07);
    CHECK(fine.k_max < coarse.k_max / 3);  // halving h: about 4x smaller
    CHECK(finer.k_max < fine.k_max / 3);
    CHECK(finer.k_max < 0.005);
    CHECK(finer.dir_max < 1e-3);
    // C is one derivative higher: first-order at worst, 10% relative at the finest level.
    CHECK(fine.c_rms < coarse.c_rms);
    CHECK(finer.c_rms < fine.c_rms);
    CHECK(finer.c_rms < 0.1);
}

TEST_CASE("Ellipsoid mean and Gaussian curvature match the analytic values", "[curvature][ellipsoid]") {
    const double a = 1.5, b = 1.0, c = 0.6;
    // For x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 with q = x^2/a^4 + y^2/b^4 + z^2/c^4:
    // K = 1 / (a^2 b^2 c^2 q^2),  H = (a^2 + b^2 + c^2 - |p|^2) / (2 a^2 b^2 c^2 q^(3/2)).
    auto rms_error = [&](int levels) {
        const Mesh m = make_ellipsoid(float(a), float(b), float(c), levels);
        const SurfaceFields s = compute_surface_fields(m);
        double eh = 0, ek = 0, nh = 0, nk = 0;
        for (size_t i = 0; i < s.size(); ++i) {
            const glm::dvec3 p = m.positions[i];
            const double q = p.x * p.x / std::pow(a, 4) + p.y * p.y / std::pow(b, 4) + p.z * p.z / std::pow(c, 4);
            const double abc2 = a * a * b * b * c * c;
            const double K = 1.0 / (abc2 * q * q);
            const double H = (a * a + b * b + c * c - glm::dot(p, p)) / (2 * abc2 * std::pow(q, 1.5));
            eh += std::pow(0.5 * (s.k1[i] + s.k2[i]) - H, 2);
            ek += std::pow(double(s.k1[i]) * s.k2[i] - K, 2);
            nh += H * H;
            nk += K * K;
        }
        return std::make_pair(std::sqrt(eh / nh), std::sqrt(ek / nk));
    };
    const auto coarse = rms_error(4), fine = rms_error(5), finer = rms_error(6);
    INFO("relative rms error H, K: " << coarse.first << ", " << coarse.second << " -> " << fine.first << ", "
                                     << fine.second << " -> " << finer.first << ", " << finer.second);
    // A subdivided icosahedron is not a regular grid (valence-5 vertices, varying triangle
    // shapes): the estimate is first-order there, errors about proportional to the edge length h
    // (0.07, 0.035, 0.018 for levels 4, 5, 6 on these axes). Allow 0.4 h.
    const double h[3] = {0.07, 0.035, 0.018};
    CHECK(coarse.first < 0.4 * h[0]);
    CHECK(fine.first < 0.4 * h[1]);
    CHECK(finer.first < 0.4 * h[2]);
    CHECK(coarse.second < 0.4 * h[0]);
    CHECK(fine.second < 0.4 * h[1]);
    CHECK(finer.second < 0.4 * h[2]);
    CHECK(fine.first < coarse.first / 1.4);  // and they shrink with refinement
    CHECK(finer.first < fine.first / 1.4);
}

TEST_CASE("curvature fields are the same bits for any thread count", "[curvature][determinism]") {
    // The face fits run a few faces at a time (double_lanes.h) and the rest
    // one by one; thread ranges that split the faces at odd places move
    // faces between the two, which must not change a bit.
    const Mesh bunny = load_mesh(test::shared_mesh("bunny.ply"));  // 69,451 faces: odd splits
    auto fields_with = [&](unsigned threads) {
        set_thread_count(threads);
        return compute_surface_fields(bunny, {});
    };
    const SurfaceFields one = fields_with(1);
    for (unsigned threads : {2u, 3u, 5u}) {
        const SurfaceFields other = fields_with(threads);
        CHECK(std::memcmp(one.k1.data(), other.k1.data(), one.k1.size() * sizeof(float)) == 0);
        CHECK(std::memcmp(one.k2.data(), other.k2.data(), one.k2.size() * sizeof(float)) == 0);
        CHECK(std::memcmp(one.d1.data(), other.d1.data(), one.d1.size() * sizeof(glm::vec3)) == 0);
        CHECK(std::memcmp(one.dcurv.data(), other.dcurv.data(), one.dcurv.size() * sizeof(glm::vec4)) == 0);
        CHECK(one.flags == other.flags);
        CHECK(std::memcmp(one.normals.data(), other.normals.data(), one.normals.size() * sizeof(glm::vec3)) == 0);
    }
    set_thread_count(0);
}

TEST_CASE("curvature fields are the same bits with and without AVX2", "[curvature][determinism]") {
    // The face fits run four faces at a time in a version compiled for AVX2
    // where the processor has it, two at a time otherwise (double_lanes.h).
    const Mesh bunny = load_mesh(test::shared_mesh("bunny.ply"));
    lanes::allow_avx2(false);
    const SurfaceFields baseline = compute_surface_fields(bunny, {});
    lanes::allow_avx2(true);
    const SurfaceFields widest = compute_surface_fields(bunny, {});
    CHECK(std::memcmp(baseline.k1.data(), widest.k1.data(), baseline.k1.size() * sizeof(float)) == 0);
    CHECK(std::memcmp(baseline.d1.data(), widest.d1.data(), baseline.d1.size() * sizeof(glm::vec3)) == 0);
    // The face records also carry the vertex indices the flags come from.
    CHECK(baseline.flags == widest.flags);
    CHECK(std::memcmp(baseline.normals.data(), widest.normals.data(), baseline.normals.size() * sizeof(glm::vec3)) == 0);
    CHECK(std::memcmp(baseline.point_areas.data(), widest.point_areas.data(), baseline.point_areas.size() * sizeof(float)) == 0);
    CHECK(std::memcmp(baseline.dcurv.data(), widest.dcurv.data(), baseline.dcurv.size() * sizeof(glm::vec4)) == 0);
}
