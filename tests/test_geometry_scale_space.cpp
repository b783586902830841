// The scale space (geometry/scale/scale_space.h) and its clusters
// (surface_clusters.h): structure of the clusters, exactness at and below
// the raw scale, accuracy at larger scales on analytic surfaces (bounds from
// measurements on 2026-11-23, printed by INFO, with margins), noise removal,
// determinism and robustness.
#include "analytic_curvature.h"
#include "test_support.h"

#include "geometry/io/mesh_io.h"

#include "geometry/parallel/parallel.h"
#include "geometry/mesh/primitives.h"
#include "geometry/scale/pixel_scale.h"
#include "geometry/scale/raw_consistency.h"
#include "geometry/scale/scale_space.h"
#include "geometry/scale/surface_clusters.h"
#include "geometry/surface_analysis.h"

#include <glm/common.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <set>

using namespace kappa;

namespace {

bool all_finite(const SurfaceFields& f) {
    for (size_t v = 0; v < f.size(); ++v) {
        const float values[] = {f.normals[v].x, f.normals[v].y, f.normals[v].z, f.k1[v], f.k2[v], f.d1[v].x,
                                f.d1[v].y,      f.d1[v].z,      f.d2[v].x,      f.d2[v].y, f.d2[v].z,
                                f.dcurv[v].x,   f.dcurv[v].y,   f.dcurv[v].z,   f.dcurv[v].w};
        for (float x : values)
            if (!std::isfinite(x)) return false;
    }
    return true;
}

// Relative RMS error of |C| = sqrt(a^2 + 3b^2 + 3c^2 + d^2) against the
// torus's sqrt(3) R |sin v| / (r (R + r cos v)^2) (conventions.md).
double torus_dcurv_error(const Mesh& mesh, const SurfaceFields& f, double R, double r) {
    double err = 0, ref = 0;
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
        const glm::dvec3 p(mesh.positions[i]);
        const double v = std::atan2(p.z, std::hypot(p.x, p.y) - R);
        const double truth = std::sqrt(3.0) * R * std::fabs(std::sin(v)) / (r * std::pow(R + r * std::cos(v), 2));
        const double est = dcurv_norm(glm::dvec4(f.dcurv[i]));
        err += (est - truth) * (est - truth);
        ref += truth * truth;
    }
    return std::sqrt(err / ref);
}

}  // namespace

TEST_CASE("Surface clusters partition the vertices into connected pieces of one cell", "[scale-space]") {
    const Mesh mesh = make_torus(1.0f, 0.4f, 120, 60);
    const SurfaceFields raw = compute_surface_fields(mesh);
    const float cell = 0.15f;
    const ClusterLevel level = build_surface_clusters(mesh, raw.point_areas, raw.normals, glm::vec3(-1.5f), cell);
    REQUIRE(level.built());
    REQUIRE(level.vertex_cluster.size() == mesh.vertex_count());
    // One cell per cluster; the areas add up; adjacency is symmetric, with no self-loops.
    std::vector<glm::ivec3> cell_of(level.size(), glm::ivec3(INT32_MIN));
    double area = 0, total = 0;
    for (size_t v = 0; v < mesh.vertex_count(); ++v) {
        const glm::ivec3 key(glm::floor((mesh.positions[v] - glm::vec3(-1.5f)) / cell));
        const uint32_t c = level.vertex_cluster[v];
        REQUIRE(c < level.size());
        if (cell_of[c].x == INT32_MIN) cell_of[c] = key;
        CHECK(cell_of[c] == key);
        total += raw.point_areas[v];
    }
    for (float a : level.area) area += a;
    CHECK(area == Approx(total).epsilon(1e-4));
    for (uint32_t c = 0; c < level.size(); ++c)
        for (uint32_t k = level.adj_offsets[c]; k < level.adj_offsets[c + 1]; ++k) {
            const uint32_t d = level.adj[k];
            CHECK(d != c);
            const auto first = level.adj.begin() + level.adj_offsets[d], last = level.adj.begin() + level.adj_offsets[d + 1];
            CHECK(std::find(first, last, c) != last);
        }
    // A torus with cells of 0.15 has thousands of clusters, each a few cells' worth of vertices.
    CHECK(level.size() > 500);
    CHECK(level.size() < mesh.vertex_count() / 4);
}

TEST_CASE("Surface clusters keep the two sides of a thin sheet apart", "[scale-space]") {
    // Two parallel grids 0.01 apart (less than a cell) are never one cluster.
    Mesh a = make_grid(1.0f, 20), b = make_grid(1.0f, 20);
    Mesh mesh = a;
    for (auto& p : b.positions) p.z += 0.01f;
    const uint32_t offset = uint32_t(mesh.vertex_count());
    mesh.positions.insert(mesh.positions.end(), b.positions.begin(), b.positions.end());
    for (Face f : b.faces) mesh.faces.push_back(f + Face(offset));
    const SurfaceFields raw = compute_surface_fields(mesh);
    const ClusterLevel level = build_surface_clusters(mesh, raw.point_areas, raw.normals, glm::vec3(-1), 0.2f);
    std::set<uint32_t> top(level.vertex_cluster.begin(), level.vertex_cluster.begin() + offset);
    for (size_t v = offset; v < mesh.vertex_count(); ++v) CHECK(top.count(level.vertex_cluster[v]) == 0);
}

TEST_CASE("Fields at or below the raw scale are the raw fields, bit for bit", "[scale-space]") {
    const Mesh mesh = make_jittered_sphere(1.0f, 4, 0.6f, 5);
    const SurfaceFields raw = compute_surface_fields(mesh);
    ScaleSpace space = build_scale_space(mesh);
    REQUIRE(!space.empty());
    for (float sigma : {0.0f, 0.5f * space.raw_scale, space.raw_scale}) {
        const SurfaceFields f = fields_at_scale(mesh, space, raw, sigma);
        CHECK(f.normals == raw.normals);
        CHECK(f.k1 == raw.k1);
        CHECK(f.k2 == raw.k2);
        CHECK(f.d1 == raw.d1);
        CHECK(f.dcurv == raw.dcurv);
    }
}

TEST_CASE("A sphere keeps its curvature 1/R and C = 0 at every scale", "[scale-space]") {
    const float R = 2.0f;
    const Mesh mesh = make_jittered_sphere(R, 5, 0.6f, 9);
    const SurfaceFields raw = compute_surface_fields(mesh);
    ScaleSpace space = build_scale_space(mesh);
    const float h = mean_edge_length(mesh);
    for (float edges : {1.0f, 3.0f, 8.0f, 20.0f}) {  // 20 edges: beyond the top level (R / 4)
        const SurfaceFields f = fields_at_scale(mesh, space, raw, edges * h);
        double k_err = 0, c_max = 0, n_err = 0;
        for (size_t v = 0; v < mesh.vertex_count(); ++v) {
            k_err = std::max({k_err, std::fabs(double(f.k1[v]) * R - 1), std::fabs(double(f.k2[v]) * R - 1)});
            const glm::dvec4 C(f.dcurv[v]);
            c_max = std::max(c_max, std::sqrt(glm::dot(C, C)) * R * R);
            n_err = std::max(n_err, double(glm::length(f.normals[v] - mesh.positions[v] / R)));
        }
        INFO("sigma " << edges << " edges: max |k R - 1| " << k_err << ", max |C| R^2 " << c_max
                      << ", max normal error " << n_err);
        // Measured: |k R - 1| <= 0.045; |C| R^2 0.52 at 1 edge (mostly the
        // raw estimate), <= 0.19 from 3 edges; normal error <= 0.0071.
        CHECK(k_err < 0.08);
        CHECK(c_max < (edges < 2 ? 1.0 : 0.4));
        CHECK(n_err < 0.02);
        CHECK(all_finite(f));
    }
}

TEST_CASE("Curvature and C at a scale are accurate on a torus, and remove noise", "[scale-space]") {
    const double R = 1, r = 0.4;
    test::AnalyticMesh torus = test::analytic_torus(R, r, 200, 100);
    const float h = mean_edge_length(torus.mesh);
    {
        const SurfaceFields raw = compute_surface_fields(torus.mesh);
        ScaleSpace space = build_scale_space(torus.mesh);
        const SurfaceFields f = fields_at_scale(torus.mesh, space, raw, 3 * h);
        const double e = test::relative_curvature_error(f, torus);
        const double ec = torus_dcurv_error(torus.mesh, f, R, r);
        INFO("clean torus at 3 edges: curvature error " << e << ", |C| error " << ec);
        // Measured: 0.017 and 0.059.
        CHECK(e < 0.03);
        CHECK(ec < 0.12);
    }
    // The noisy torus (2% of an edge): raw error about 0.32.
    test::AnalyticMesh noisy = torus;
    add_normal_noise(noisy.mesh, 0.02f * h, 11);
    const SurfaceFields raw = compute_surface_fields(noisy.mesh);
    ScaleSpace space = build_scale_space(noisy.mesh);
    const double e_raw = test::relative_curvature_error(raw, noisy);
    const SurfaceFields f = fields_at_scale(noisy.mesh, space, raw, 3 * h);
    const double e = test::relative_curvature_error(f, noisy);
    INFO("noisy torus: raw error " << e_raw << ", at 3 edges " << e);
    CHECK(e_raw > 0.2);
    CHECK(e < 0.035);  // measured 0.017 (the public figures: 0.05 libigl, 0.03 CGAL)
}

TEST_CASE("The raw C is scale-consistent where it is accurate: regular tessellations, not irregular ones",
          "[scale-space]") {
    // The accuracy lab's torus, its vertices jittered by 0 to 0.3 cells.
    // Measured 2026-11-25 (ratio, C error raw / level 0): jitter 0: 0.73,
    // 0.002 / 0.097; 0.1: 2.47, 0.30 / 0.11; 0.3: 10.5, 1.18 / 0.14.
    for (double jitter : {0.0, 0.1, 0.3}) {
        const test::AnalyticMesh torus = test::analytic_torus(1, 0.4, 200, 100, jitter, 100);
        const SurfaceFields raw = compute_surface_fields(torus.mesh);
        ScaleSpace space = build_scale_space(torus.mesh);
        const RawConsistency c = raw_dcurv_consistency(torus.mesh, space, raw);
        const double e_raw = test::relative_dcurv_error(raw, torus);
        const double e_first = test::relative_dcurv_error(fields_at_scale(torus.mesh, space, raw, space.level_scale(0)), torus);
        INFO("jitter " << jitter << ": |C| steps " << c.raw_to_first << " / " << c.first_to_second << ", C error raw "
                       << e_raw << ", level 0 " << e_first);
        CHECK(c.consistent == (jitter == 0.0));
        // The verdict picks the more accurate of the two.
        if (c.consistent) CHECK(e_raw < 0.5 * e_first);
        else CHECK(e_first < 0.5 * e_raw);
    }
    // Fandisk (an irregular CAD tessellation): ratio 4.9. A sphere-based
    // model, regular or jittered: 0.8 (its bumps change C from level to level).
    const Mesh fandisk = load_mesh(test::shared_mesh("fandisk.obj"));
    const SurfaceFields fandisk_raw = compute_surface_fields(fandisk);
    ScaleSpace fandisk_space = build_scale_space(fandisk);
    CHECK_FALSE(raw_dcurv_consistency(fandisk, fandisk_space, fandisk_raw).consistent);
    const Mesh sphere = make_jittered_sphere(1.0f, 5, 0.8f, 3);
    const SurfaceFields sphere_raw = compute_surface_fields(sphere);
    ScaleSpace sphere_space = build_scale_space(sphere);
    CHECK(raw_dcurv_consistency(sphere, sphere_space, sphere_raw).consistent);
}

TEST_CASE("Larger scales smooth scan-like noise away", "[scale-space]") {
    Mesh mesh = make_icosphere(1.0f, 6);
    const float h = mean_edge_length(mesh);
    add_normal_noise(mesh, 0.3f * h, 3);
    const SurfaceFields raw = compute_surface_fields(mesh);
    ScaleSpace space = build_scale_space(mesh);
    double previous = 1e30;
    for (float edges : {0.0f, 2.0f, 4.0f, 8.0f, 16.0f}) {
        const SurfaceFields f = fields_at_scale(mesh, space, raw, edges * h);
        double spread = 0;  // RMS of k - 1 (unit sphere)
        for (size_t v = 0; v < mesh.vertex_count(); ++v)
            spread += std::pow(f.k1[v] - 1.0, 2) + std::pow(f.k2[v] - 1.0, 2);
        spread = std::sqrt(spread / double(2 * mesh.vertex_count()));
        INFO("sigma " << edges << " edges: RMS |k - 1| " << spread);
        CHECK(spread < previous);
        previous = spread;
    }
    CHECK(previous < 0.05);  // measured 0.012 at 16 edges; raw 6.7
}

TEST_CASE("The surface at a scale keeps a sphere's radius and takes scan noise away", "[scale-space]") {
    // surface_at_scale moves each vertex onto its levels' fitted quadrics,
    // each raised by its height (level_fit.h) over its centroid, which lies
    // inside a curved patch: without the height the sphere would shrink.
    const float R = 2.0f;
    const Mesh clean = make_jittered_sphere(R, 5, 0.6f, 9);
    const float h = mean_edge_length(clean);
    Mesh noisy = clean;
    add_normal_noise(noisy, 0.33f * h, 5);
    for (const Mesh* mesh : {&clean, static_cast<const Mesh*>(&noisy)}) {
        const SurfaceFields raw = compute_surface_normals(*mesh);
        ScaleSpace space = build_scale_space(*mesh);
        for (float edges : {0.25f, 4.0f, 12.0f}) {
            const std::vector<float> sigma(mesh->vertex_count(), edges * h);
            const SurfaceAtScale s = surface_at_scale(*mesh, space, raw, sigma);
            double sum = 0, rms_before = 0, largest = 0;
            for (size_t v = 0; v < mesh->vertex_count(); ++v) {
                const double e = glm::length(s.positions[v]) - R, before = glm::length(mesh->positions[v]) - R;
                sum += e, rms_before += before * before;
                largest = std::max(largest, double(glm::length(s.positions[v] - mesh->positions[v])));
                CHECK(glm::dot(s.normals[v], s.positions[v]) > 0);
            }
            double rms = 0;
            const double mean = sum / double(mesh->vertex_count());
            for (size_t v = 0; v < mesh->vertex_count(); ++v)
                rms += std::pow(glm::length(s.positions[v]) - R - mean, 2);
            rms = std::sqrt(rms / double(mesh->vertex_count()));
            rms_before = std::sqrt(rms_before / double(mesh->vertex_count()));
            INFO((mesh == &clean ? "clean" : "noisy") << ", sigma " << edges << " edges: mean radius error "
                 << mean / h << " edges, RMS about it " << rms / h << " (before " << rms_before / h
                 << "), largest move " << largest / h);
            CHECK(largest <= edges * h * 1.0001);  // never further than the scale
            if (edges < 0.5f) {
                CHECK(largest == 0);  // below the raw scale: the mesh's own positions
                continue;
            }
            CHECK(std::fabs(mean) < 0.02 * h);  // no shrinkage
            if (mesh == &noisy) CHECK(rms < 0.1 * h);   // the noise (0.33 edges) is gone
            else CHECK(rms < 0.01 * h);
        }
    }
}

TEST_CASE("Fields at a scale do not depend on the thread count", "[scale-space]") {
    Mesh mesh = make_torus(1.0f, 0.3f, 150, 50);
    add_normal_noise(mesh, 0.002f, 4);
    const SurfaceFields raw = compute_surface_fields(mesh);
    std::vector<float> sigma(mesh.vertex_count());
    for (size_t v = 0; v < sigma.size(); ++v) sigma[v] = 0.005f + 0.05f * (mesh.positions[v].x + 1.5f);  // varies
    SurfaceFields out[3];
    SurfaceAtScale surface[3];
    const unsigned threads[] = {1, 2, 5};
    for (int i = 0; i < 3; ++i) {
        set_thread_count(threads[i]);
        ScaleSpace space = build_scale_space(mesh);
        out[i] = fields_at_scale(mesh, space, raw, sigma);
        surface[i] = surface_at_scale(mesh, space, raw, sigma);
    }
    set_thread_count(0);
    for (int i = 1; i < 3; ++i) {
        CHECK(surface[i].positions == surface[0].positions);
        CHECK(surface[i].normals == surface[0].normals);
        CHECK(out[i].normals == out[0].normals);
        CHECK(out[i].k1 == out[0].k1);
        CHECK(out[i].k2 == out[0].k2);
        CHECK(out[i].d1 == out[0].d1);
        CHECK(out[i].dcurv == out[0].dcurv);
    }
}

TEST_CASE("Fields and surface at a scale are the same, bit for bit, with the levels' values at the vertices kept",
          "[scale-space]") {
    // Views of varying scales, in pieces as a page blends them: each with a fresh space (nothing kept)
    // and with one space that keeps the values from view to view (level_value_cache.h), also when
    // the budgets hold one level or none.
    Mesh mesh = make_torus(1.0f, 0.3f, 150, 50);
    add_normal_noise(mesh, 0.002f, 4);
    const SurfaceFields raw = compute_surface_fields(mesh);
    auto view_sigma = [&](int view) {
        std::vector<float> sigma(mesh.vertex_count());
        for (size_t v = 0; v < sigma.size(); ++v)
            sigma[v] = (0.004f + 0.03f * float(view)) * (1.2f + mesh.positions[v].x);  // up to the top level
        return sigma;
    };
    struct Blended {
        SurfaceFields fields;
        SurfaceAtScale surface;
    };
    auto blended = [&](ScaleSpace& space, const std::vector<float>& sigma) {
        fit_levels(mesh, space, raw, levels_to_fit(space, sigma));
        Blended out{fields_to_blend(mesh, raw), {mesh.positions, raw.normals}};
        for (size_t first = 0; first < mesh.vertex_count(); first += 1000) {
            const size_t last = std::min(first + 1000, mesh.vertex_count());
            blend_fields(mesh, space, raw, sigma, first, last, out.fields);
            blend_surface(mesh, space, raw, sigma, first, last, out.surface);
        }
        return out;
    };
    REQUIRE(build_scale_space(mesh).levels.size() >= 3);
    for (const double levels_budgeted : {1000.0, 1.0, 0.5}) {
        ScaleSpace kept = build_scale_space(mesh);
        kept.keep_level_values(true);
        for (LevelValueCache* cache : {&kept.tensor_values, &kept.surface_values})
            cache->set_budget_bytes(size_t(levels_budgeted * double(cache->level_bytes(mesh.vertex_count()))));
        for (int pass = 0; pass < 2; ++pass)  // the second pass reads back what the first kept
            for (int view = 0; view < 4; ++view) {
                INFO("levels budgeted " << levels_budgeted << ", pass " << pass << ", view " << view);
                const std::vector<float> sigma = view_sigma(view);
                ScaleSpace fresh = build_scale_space(mesh);
                const Blended expected = blended(fresh, sigma), got = blended(kept, sigma);
                CHECK(got.fields.normals == expected.fields.normals);
                CHECK(got.fields.k1 == expected.fields.k1);
                CHECK(got.fields.k2 == expected.fields.k2);
                CHECK(got.fields.d1 == expected.fields.d1);
                CHECK(got.fields.d2 == expected.fields.d2);
                CHECK(got.fields.dcurv == expected.fields.dcurv);
                CHECK(got.surface.positions == expected.surface.positions);
                CHECK(got.surface.normals == expected.surface.normals);
                for (const LevelValueCache* cache : {&kept.tensor_values, &kept.surface_values}) {
                    if (view > 0) CHECK((cache->bytes() > 0) == (levels_budgeted >= 1));  // view 0: raw only
                    CHECK(cache->bytes() <= cache->budget_bytes());
                }
                const ScaleSpace copy = kept;  // keeps nothing
                CHECK(copy.tensor_values.bytes() + copy.surface_values.bytes() == 0);
            }
    }
}

TEST_CASE("Degenerate input gives finite fields at every scale", "[scale-space]") {
    // A torus with an isolated vertex, a zero-area face, a tiny separate
    // triangle and a duplicated vertex position.
    Mesh mesh = make_torus(1.0f, 0.4f, 40, 20);
    const uint32_t n = uint32_t(mesh.vertex_count());
    mesh.positions.push_back({5, 5, 5});                                   // isolated
    mesh.positions.push_back(mesh.positions[0]);                           // duplicate position
    mesh.faces.push_back({0, 1, n + 1});                                   // zero-area face
    mesh.positions.insert(mesh.positions.end(), {{3, 0, 0}, {3.001f, 0, 0}, {3, 0.001f, 0}});
    mesh.faces.push_back({n + 2, n + 3, n + 4});                           // tiny component
    const SurfaceFields raw = compute_surface_fields(mesh);
    ScaleSpace space = build_scale_space(mesh);
    for (float sigma : {0.01f, 0.1f, 0.5f, 5.0f}) {
        const SurfaceFields f = fields_at_scale(mesh, space, raw, sigma);
        CHECK(all_finite(f));
        CHECK(f.k1[n] == raw.k1[n]);  // flagged vertices keep their raw values
    }
    Mesh empty;
    ScaleSpace none = build_scale_space(empty);
    CHECK(none.empty());
}

TEST_CASE("Pixel size grows with depth along the view direction", "[scale-space]") {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {0, 0, -1}, {1, 1, -3}};
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 2), glm::vec3(0), glm::vec3(0, 1, 0));
    const std::vector<float> px = pixel_sizes(mesh, view, 60.0f, 600);
    const float per_depth = 2.0f * std::tan(glm::radians(30.0f)) / 600.0f;
    CHECK(px[0] == Approx(2 * per_depth));
    CHECK(px[1] == Approx(3 * per_depth));
    CHECK(px[2] == Approx(5 * per_depth));
}
