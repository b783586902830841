// The frame changes of the curvature steps (Rusinkiewicz 2004, sec. 3.3):
// the rotation kept per (vertex, face) corner against trimesh2's
// rotate-then-project formulas, written independently in tensor_frames.h.
#include "geometry/curvature/tensor_frames.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <random>

using namespace kappa;

namespace {

glm::vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
}

// A face frame (t, b) with normal nf = t x b, t in a random direction.
void random_face_frame(std::mt19937& rng, glm::vec3& t, glm::vec3& b, glm::vec3& nf) {
    nf = random_unit(rng);
    t = glm::normalize(glm::cross(nf, random_unit(rng)));
    b = glm::cross(nf, t);
}

// frame_rotation in doubles, as the curvature step runs it, rounded to float.
FrameRotation rotation_of(const glm::vec3& t, const glm::vec3& b, const glm::vec3& nf, const glm::vec3& u,
                          const glm::vec3& nv) {
    auto v = [](const glm::vec3& x) { return lanes::Vec3<double>{x.x, x.y, x.z}; };
    double c, s;
    frame_rotation<double>(v(t), v(b), v(nf), v(u), v(nv), c, s);
    return {float(c), float(s)};
}

}  // namespace

TEST_CASE("frame_rotation is the rotation rotate_frame gives, and moves tensors as project_tensor does",
          "[curvature]") {
    std::mt19937 rng(11);
    int checked = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        glm::vec3 t, b, nf, u, v;
        random_face_frame(rng, t, b, nf);
        glm::vec3 nv = random_unit(rng);
        if (trial % 2) nv = glm::normalize(nf + 0.3f * nv);  // the usual case: normals close together
        if (glm::dot(nv, nf) < -0.9f) continue;            // near opposite: ill-conditioned in float
        tangent_frame(nv, u, v);
        const FrameRotation r = rotation_of(t, b, nf, u, nv);
        // A rotation: unit (c, s); rotated u = c t + s b and rotated v = -s t + c b.
        REQUIRE(r.c * r.c + r.s * r.s == Approx(1.0f).margin(1e-5));
        glm::vec3 ru, rv;
        rotate_frame(u, v, nf, ru, rv);
        REQUIRE(glm::length(ru - (r.c * t + r.s * b)) < 1e-5f);
        REQUIRE(glm::length(rv - (-r.s * t + r.c * b)) < 1e-5f);
        // A face tensor in (t, b) re-expressed in (u, v): as project_tensor.
        const Tensor2 face{2.5f, -0.7f, -1.3f};
        const Tensor2 a = transform_tensor(r.change(), face), ref = project_tensor(t, b, face, u, v);
        REQUIRE(a.ku == Approx(ref.ku).margin(2e-5));
        REQUIRE(a.kuv == Approx(ref.kuv).margin(2e-5));
        REQUIRE(a.kv == Approx(ref.kv).margin(2e-5));
        const glm::vec4 C(1.5f, -0.4f, 0.9f, 2.0f);
        const glm::vec4 dc = transform_dcurv(r.change(), C), dref = project_dcurv(t, b, C, u, v);
        for (int k = 0; k < 4; ++k) REQUIRE(dc[k] == Approx(dref[k]).margin(3e-5));
        ++checked;
    }
    CHECK(checked > 4000);
}

TEST_CASE("frame_rotation of exactly opposite normals is a half turn about t, a proper rotation", "[curvature]") {
    // Face frame: t = x, b = y, nf = z; vertex normal -z. rotate_frame's axis is
    // undefined there; a half turn about t maps (x, y, z) to (x, -y, -z).
    const glm::vec3 t(1, 0, 0), b(0, 1, 0), nf(0, 0, 1), nv(0, 0, -1);
    glm::vec3 u, v;
    tangent_frame(nv, u, v);
    const FrameRotation r = rotation_of(t, b, nf, u, nv);
    CHECK(r.c * r.c + r.s * r.s == Approx(1.0f));
    const glm::vec3 turned_u(u.x, -u.y, -u.z), turned_v(v.x, -v.y, -v.z);
    CHECK(glm::length(turned_u - (r.c * t + r.s * b)) < 1e-6f);
    CHECK(glm::length(turned_v - (-r.s * t + r.c * b)) < 1e-6f);
    // The turned frame's normal is nf: a rotation, not a reflection.
    CHECK(glm::dot(glm::cross(turned_u, turned_v), nf) == Approx(1.0f));
}

TEST_CASE("C turned through its harmonics is C turned by transform_dcurv", "[curvature]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> coefficient(-3, 3), angle(-3.2f, 3.2f);
    for (int trial = 0; trial < 2000; ++trial) {
        const glm::vec4 C(coefficient(rng), coefficient(rng), coefficient(rng), coefficient(rng));
        const glm::vec4 back = dcurv_from_harmonics(dcurv_harmonics(C));
        for (int k = 0; k < 4; ++k) REQUIRE(back[k] == Approx(C[k]).margin(2e-6));
        const float phi = angle(rng);
        const FrameRotation r{std::cos(phi), std::sin(phi)};
        const glm::vec4 turned = dcurv_from_harmonics(turn_dcurv_harmonics(dcurv_harmonics(C), r.c, r.s));
        const glm::vec4 ref = transform_dcurv(r.change(), C);
        for (int k = 0; k < 4; ++k) REQUIRE(turned[k] == Approx(ref[k]).margin(1e-5));
    }
}

TEST_CASE("a tensor turned through its harmonics is the tensor turned by transform_tensor", "[curvature]") {
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> coefficient(-3, 3), angle(-3.2f, 3.2f);
    for (int trial = 0; trial < 2000; ++trial) {
        const Tensor2 T{coefficient(rng), coefficient(rng), coefficient(rng)};
        const float phi = angle(rng);
        const FrameRotation r{std::cos(phi), std::sin(phi)};
        const Tensor2 turned = tensor_from_harmonics(turn_tensor_harmonics(tensor_harmonics(T), r.c, r.s));
        const Tensor2 ref = transform_tensor(r.change(), T);
        REQUIRE(turned.ku == Approx(ref.ku).margin(1e-5));
        REQUIRE(turned.kuv == Approx(ref.kuv).margin(1e-5));
        REQUIRE(turned.kv == Approx(ref.kv).margin(1e-5));
    }
}
