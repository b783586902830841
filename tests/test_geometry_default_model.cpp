// The built-in model: closed, outward, deterministic, with both convex and
// concave regions (needed for suggestive contours).
#include <catch2/catch.hpp>

#include "geometry/mesh/default_model.h"
#include "geometry/mesh/mesh_stats.h"

#include <glm/geometric.hpp>

#include <cstring>

using namespace kappa;

TEST_CASE("default model is a closed manifold of the planned size", "[default_model]") {
    const Mesh m = make_default_model();
    CHECK(m.face_count() >= 50000);
    CHECK(m.face_count() <= 200000);
    const MeshStats s = compute_mesh_stats(m);
    CHECK(s.topology.boundary_edges == 0);
    CHECK(s.topology.nonmanifold_edges == 0);
    CHECK(s.topology.components == 1);
    CHECK(s.topology.isolated_vertices == 0);
    CHECK(s.topology.euler_characteristic == 2);
    CHECK(s.degenerate_faces == 0);
}

TEST_CASE("default model is deterministic", "[default_model]") {
    const Mesh a = make_default_model(), b = make_default_model();
    REQUIRE(a.positions.size() == b.positions.size());
    REQUIRE(a.faces == b.faces);
    CHECK(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::vec3)) == 0);
}

TEST_CASE("default model: radius 1, centred, faces outward", "[default_model]") {
    const Mesh m = make_default_model();
    float farthest = 0;
    for (const auto& p : m.positions) farthest = std::max(farthest, glm::length(p));
    CHECK(farthest == Approx(1.0f).epsilon(1e-5));
    const BoundingBox box = bounding_box(m);
    CHECK(glm::length(box.center()) < 1e-5f);

    // Signed volume (divergence theorem): positive iff faces are CCW from outside.
    double volume = 0;
    size_t facing_out = 0;
    for (const Face& f : m.faces) {
        const glm::dvec3 a(m.positions[f[0]]), b(m.positions[f[1]]), c(m.positions[f[2]]);
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
        facing_out += glm::dot(glm::cross(b - a, c - a), a + b + c) > 0;
    }
    CHECK(volume > 1.0);  // a unit ball holds 4.19; the model fills much of its bounding ball
    // Nearly every face looks away from the centre (the shape is a displaced sphere).
    CHECK(facing_out > 0.99 * double(m.face_count()));
}

TEST_CASE("default model has convex and concave regions", "[default_model]") {
    // Umbrella Laplacian (mean of neighbours minus the vertex) along the outward
    // direction: negative on convex regions, positive on concave ones.
    const Mesh m = make_default_model();
    std::vector<glm::vec3> sum(m.vertex_count(), glm::vec3(0));
    std::vector<int> count(m.vertex_count(), 0);
    for (const Face& f : m.faces)
        for (int i = 0; i < 3; ++i) {
            sum[f[i]] += m.positions[f[(i + 1) % 3]];
            ++count[f[i]];
        }
    size_t convex = 0, concave = 0;
    const float eps = 1e-6f;
    for (size_t v = 0; v < m.vertex_count(); ++v) {
        const glm::vec3 p = m.positions[v];
        const float along = glm::dot(sum[v] / float(count[v]) - p, glm::normalize(p));
        convex += along < -eps;
        concave += along > eps;
    }
    const double n = double(m.vertex_count());
    CHECK(convex > 0.5 * n);
    CHECK(concave > 0.05 * n);
}
