// The analytic stand-in fields used by the render tests agree with the
// curvature engine (so the tests check the renderer against the same
// conventions as the rest of kappa).
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"

#include "geometry/mesh/primitives.h"
#include "geometry/surface_analysis.h"

#include <glm/geometric.hpp>

#include <cmath>

using namespace kappa;

namespace {

// C(x, x, x) for a 3D tangent vector x, in the frame (d1, d2) of vertex i.
float cubic(const SurfaceFields& f, size_t i, glm::vec3 x) {
    const float s1 = glm::dot(x, f.d1[i]), s2 = glm::dot(x, f.d2[i]);
    const glm::vec4 C = f.dcurv[i];
    return C.x * s1 * s1 * s1 + 3 * C.y * s1 * s1 * s2 + 3 * C.z * s1 * s2 * s2 + C.w * s2 * s2 * s2;
}

}  // namespace

TEST_CASE("the exact torus fields match the curvature engine", "[render][fixtures]") {
    const Mesh torus = make_torus(1.0f, 0.4f, 160, 64);
    const SurfaceFields exact = test::torus_fields(torus, 1.0f, 0.4f);
    const SurfaceFields estimated = compute_surface_fields(torus);
    float worst_k = 0, worst_c = 0, scale_c = 0;
    for (size_t i = 0; i < torus.vertex_count(); i += 7) {
        CHECK(glm::dot(exact.normals[i], estimated.normals[i]) > 0.999f);
        worst_k = std::max({worst_k, std::abs(exact.k1[i] - estimated.k1[i]), std::abs(exact.k2[i] - estimated.k2[i])});
        // Compare the frame-independent cubic form along a few directions.
        for (float a : {0.0f, 0.7f, 1.9f, 2.6f}) {
            const glm::vec3 x = std::cos(a) * exact.d1[i] + std::sin(a) * exact.d2[i];
            worst_c = std::max(worst_c, std::abs(cubic(exact, i, x) - cubic(estimated, i, x)));
            scale_c = std::max(scale_c, std::abs(cubic(exact, i, x)));
        }
    }
    CHECK(worst_k < 0.05f);
    CHECK(worst_c < 0.1f * scale_c);
}
