// The noise-level estimate (geometry/scale/noise_level.h) on clean and noisy
// analytic meshes. Tolerances come from measurements (2026-11-23, printed by
// INFO) with margins: clean meshes measured <= 0.0012 median edge lengths,
// noisy ones within 3% of the injected sigma for eta <= 0.1, 0.91 to 1.01
// times it at eta = 0.2 and 0.82 to 0.91 times it at eta = 0.5.
#include "analytic_curvature.h"

#include "geometry/curvature/face_geometry.h"
#include "geometry/curvature/vertex_basics.h"
#include "geometry/parallel/parallel.h"
#include "geometry/mesh/primitives.h"
#include "geometry/scale/noise_level.h"
#include "geometry/mesh/vertex_faces.h"

#include <catch2/catch.hpp>

using namespace kappa;

namespace {

NoiseLevel estimate(const Mesh& m) {
    const VertexFaces vf = build_vertex_faces(m);
    const FaceGeometry faces = compute_face_geometry(m);
    return estimate_noise_level(m, vf, compute_vertex_basics(vf, faces).normals);
}

}  // namespace

TEST_CASE("Noise level is near zero on clean smooth meshes", "[noise-level]") {
    const Mesh meshes[] = {make_icosphere(1.0f, 3), make_icosphere(2.0f, 6), make_torus(1.0f, 0.4f, 100, 50),
                           make_torus(1.0f, 0.25f, 256, 64), make_ellipsoid(1.0f, 0.7f, 0.5f, 3),
                           make_ellipsoid(1.0f, 0.7f, 0.5f, 5), make_grid(1.0f, 20)};
    for (const Mesh& m : meshes) {
        const NoiseLevel n = estimate(m);
        INFO("vertices " << m.vertex_count() << ", relative noise " << n.relative);
        CHECK(n.samples > 0);
        CHECK(n.median_edge > 0);
        CHECK(n.relative < 0.003);
    }
}

TEST_CASE("Noise level recovers injected normal noise", "[noise-level]") {
    const Mesh meshes[] = {make_torus(1.0f, 0.4f, 200, 100), make_torus(1.0f, 0.25f, 256, 64),
                           make_ellipsoid(1.0f, 0.7f, 0.5f, 5), test::analytic_cubic_patch(80, 0.5, 0.3, 1.0, 2).mesh};
    for (const Mesh& clean : meshes) {
        const float h = estimate(clean).median_edge;
        for (double eta : {0.005, 0.02, 0.1, 0.2, 0.5}) {
            Mesh m = clean;
            add_normal_noise(m, float(eta * h), 5);
            const NoiseLevel n = estimate(m);
            INFO("vertices " << m.vertex_count() << ", eta " << eta << ", estimated " << n.relative);
            CHECK(n.sigma == Approx(n.relative * n.median_edge).epsilon(1e-5));
            if (eta <= 0.1) {
                CHECK(n.relative == Approx(eta).epsilon(0.06));
            } else {  // biased low: the vertex normals that give the fitting frames are noisy too
                CHECK(n.relative > 0.72 * eta);
                CHECK(n.relative < 1.06 * eta);
            }
        }
    }
}

TEST_CASE("Noise level scales with the model and ignores the thread count", "[noise-level]") {
    Mesh m = make_torus(1.0f, 0.4f, 120, 60);
    add_normal_noise(m, 0.001f, 9);
    const NoiseLevel base = estimate(m);
    Mesh scaled = m;
    for (auto& p : scaled.positions) p *= 4.0f;
    const NoiseLevel big = estimate(scaled);
    CHECK(big.sigma == Approx(4 * base.sigma).epsilon(1e-3));
    CHECK(big.relative == Approx(base.relative).epsilon(1e-3));

    set_thread_count(1);
    const NoiseLevel one = estimate(m);
    set_thread_count(3);
    const NoiseLevel three = estimate(m);
    set_thread_count(0);
    CHECK(one.sigma == base.sigma);
    CHECK(three.sigma == base.sigma);
    CHECK(one.samples == three.samples);
}

TEST_CASE("add_normal_noise moves vertices along the normal by sigma", "[noise-level]") {
    const Mesh clean = make_icosphere(1.0f, 5);
    Mesh m = clean;
    add_normal_noise(m, 0.01f, 1);
    double radial2 = 0, tangential = 0;
    for (size_t i = 0; i < m.vertex_count(); ++i) {
        const glm::vec3 d = m.positions[i] - clean.positions[i];
        const float along = glm::dot(d, glm::normalize(clean.positions[i]));
        radial2 += along * along;
        tangential = std::max(tangential, double(glm::length(d - along * glm::normalize(clean.positions[i]))));
    }
    CHECK(std::sqrt(radial2 / double(m.vertex_count())) == Approx(0.01).epsilon(0.03));
    CHECK(tangential < 1e-3 * 0.01 * 10);  // along the area-weighted normal: radial up to float rounding
    Mesh again = clean;
    add_normal_noise(again, 0.01f, 1);
    CHECK(again.positions == m.positions);
}
