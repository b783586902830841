// Area-uniform surface samples (hatching seeds): on the surface, uniform by
// area in every prefix, with the interpolated normal and principal direction.
#include "geometry/mesh/primitives.h"
#include "geometry/surface_analysis.h"
#include "geometry/mesh/surface_samples.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>

using namespace kappa;

namespace {

// Within 4 standard deviations of a binomial proportion p over n draws.
void check_proportion(size_t hits, size_t n, double p) {
    const double sigma = std::sqrt(p * (1 - p) / double(n));
    INFO(hits << " of " << n << ", expected proportion " << p);
    CHECK(std::abs(double(hits) / double(n) - p) < 4 * sigma);
}

}  // namespace

TEST_CASE("surface samples lie on their faces, with unit normals and tangent directions", "[geometry][samples]") {
    const Mesh torus = make_torus(1.0f, 0.3f, 96, 48);
    const SurfaceFields fields = compute_surface_fields(torus);
    const auto samples = sample_surface(torus, fields, 20000).points;
    REQUIRE(samples.size() == 20000);
    size_t with_direction = 0;
    for (const auto& s : samples) {
        REQUIRE(s.face < torus.face_count());
        const Face& f = torus.faces[s.face];
        const glm::vec3 a = torus.positions[f[0]], b = torus.positions[f[1]], c = torus.positions[f[2]];
        const glm::vec3 n = glm::cross(b - a, c - a);
        const float area2 = glm::length(n);
        // Barycentric coordinates from sub-triangle areas: all >= 0, sum 1.
        const float w0 = glm::dot(glm::cross(b - s.position, c - s.position), n) / (area2 * area2);
        const float w1 = glm::dot(glm::cross(c - s.position, a - s.position), n) / (area2 * area2);
        CHECK(std::abs(glm::dot(s.position - a, n / area2)) < 1e-5f);
        CHECK(w0 > -1e-4f);
        CHECK(w1 > -1e-4f);
        CHECK(w0 + w1 < 1 + 1e-4f);
        CHECK(std::abs(glm::length(s.normal) - 1) < 1e-5f);
        if (s.direction == glm::vec3(0)) continue;
        ++with_direction;
        CHECK(std::abs(glm::length(s.direction) - 1) < 1e-5f);
        CHECK(std::abs(glm::dot(s.direction, s.normal)) < 1e-5f);
        // The torus's d1 (k1 = 1/r, the larger) runs around the tube: the
        // derivative of the point along the tube angle v.
        const glm::vec3 p = s.position;
        const float u = std::atan2(p.y, p.x), v = std::atan2(p.z, std::hypot(p.x, p.y) - 1.0f);
        const glm::vec3 tube(-std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v));
        CHECK(std::abs(glm::dot(s.direction, tube)) > 0.99f);
    }
    // The torus has no umbilics: every sample has a direction.
    CHECK(with_direction == samples.size());
}

TEST_CASE("surface samples are uniform by area, in every prefix", "[geometry][samples]") {
    // Two triangles of areas 1/2 and 3/2 side by side: a quarter of the
    // samples must fall in the first.
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 3, 0}};
    m.faces = {{0, 1, 2}, {1, 3, 2}};
    SurfaceFields fields;
    fields.normals.assign(4, {0, 0, 1});
    fields.d1.assign(4, {1, 0, 0});
    const SurfaceSamples sampling = sample_surface(m, fields, 40000);
    const auto& samples = sampling.points;
    for (size_t n : {size_t(40000), size_t(5000), size_t(500)}) {
        size_t first = 0;
        for (size_t i = 0; i < n; ++i) first += samples[i].face == 0;
        check_proportion(first, n, 0.25);
    }
    // Within a face the density is uniform too: the sub-triangle next to
    // vertex 0 cut at the midpoints of its edges holds a quarter of its area.
    size_t in_face = 0, near_corner = 0;
    for (const auto& s : samples)
        if (s.face == 0) ++in_face, near_corner += s.position.x + s.position.y < 0.5f;
    check_proportion(near_corner, in_face, 0.25);
    CHECK(sampling.area == Approx(2.0).epsilon(1e-12));
}

TEST_CASE("surface samples are deterministic and skip faces of zero area", "[geometry][samples]") {
    Mesh m = make_icosphere(1.0f, 2);
    const SurfaceFields fields = compute_surface_fields(m);
    const auto a = sample_surface(m, fields, 1000).points, b = sample_surface(m, fields, 1000).points;
    REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i].face == b[i].face);
        CHECK(a[i].position == b[i].position);
    }
    const auto c = sample_surface(m, fields, 1000, 7).points;
    size_t same = 0;
    for (size_t i = 0; i < a.size(); ++i) same += a[i].position == c[i].position;
    CHECK(same < 10);  // another seed, another sequence

    // A zero-area face (a repeated vertex) and an isolated vertex: never chosen.
    m.positions.push_back({5, 5, 5});
    m.faces.push_back({0, 0, 1});
    SurfaceFields padded = fields;
    padded.normals.push_back({0, 0, 1});
    padded.d1.push_back({1, 0, 0});
    for (const auto& s : sample_surface(m, padded, 5000).points) CHECK(s.face != m.face_count() - 1);

    // Zero total area: no samples.
    Mesh flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    flat.faces = {{0, 1, 2}};
    SurfaceFields line;
    line.normals.assign(3, {0, 0, 1});
    line.d1.assign(3, {1, 0, 0});
    CHECK(sample_surface(flat, line, 100).points.empty());
    CHECK(sample_surface(Mesh{}, SurfaceFields{}, 100).points.empty());
}
