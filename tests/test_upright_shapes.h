// Procedural models that stand on a base or have a long axis, for the
// default view's up axis (geometry/view/default_view.h): a bust scanned z up,
// a head scanned y up, a standing figure.
#pragma once

#include "geometry/mesh/primitives.h"
#include "test_shapes.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace kappa::test {

// An ellipsoid with semi-axes r around c, its vertices below `floor` (along
// z) moved up onto it: a flat cut.
inline Mesh ellipsoid_at(glm::vec3 c, glm::vec3 r, float floor = -INFINITY) {
    Mesh m = make_ellipsoid(r.x, r.y, r.z, 4);
    for (glm::vec3& p : m.positions) {
        p += c;
        p.z = std::max(p.z, floor);
    }
    return m;
}

// A bust, z up, face towards -y: shoulders cut flat at z = 0 (the base), a
// neck and a head with a nose.
inline Mesh bust_z_up() {
    Mesh m = ellipsoid_at({0, 0, 0.2f}, {0.8f, 0.4f, 0.45f}, 0.0f);
    append(m, ellipsoid_at({0, -0.05f, 0.65f}, {0.15f, 0.15f, 0.25f}));
    append(m, ellipsoid_at({0, -0.05f, 1.0f}, {0.3f, 0.36f, 0.42f}));
    append(m, ellipsoid_at({0, -0.42f, 0.98f}, {0.05f, 0.08f, 0.1f}));  // nose
    return m;
}

// A head, y up, face towards +z: a head with a nose and a neck cut flat at
// its bottom, y = -0.45 (ellipsoids are made z-up, then turned: z -> y).
inline Mesh head_y_up() {
    Mesh m = ellipsoid_at({0, 0, -0.35f}, {0.14f, 0.14f, 0.2f}, -0.45f);  // neck
    append(m, ellipsoid_at({0, 0, 0.1f}, {0.3f, 0.36f, 0.42f}));
    append(m, ellipsoid_at({0, -0.37f, 0.05f}, {0.05f, 0.08f, 0.1f}));  // nose at -y
    for (glm::vec3& p : m.positions) p = {p.x, p.z, -p.y};                     // z up -> y up, -y -> +z
    return m;
}

// The same head with hair: curls (small balls, in mirror pairs) over the
// back and top of the skull, more curved than the face.
inline Mesh head_with_hair_y_up() {
    Mesh m = ellipsoid_at({0, 0, -0.35f}, {0.14f, 0.14f, 0.2f}, -0.45f);  // neck
    append(m, ellipsoid_at({0, 0, 0.1f}, {0.3f, 0.36f, 0.42f}));
    append(m, ellipsoid_at({0, -0.37f, 0.05f}, {0.05f, 0.08f, 0.1f}));  // nose at -y
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 5; ++j) {
            // Directions over the back (+y) and top of the head, mirrored in x.
            const float u = 0.15f + 0.25f * float(i), v = 0.2f + 0.3f * float(j);  // radians
            const glm::vec3 d(std::sin(u) * std::cos(v), std::cos(u) * std::cos(v) * 0.8f + 0.2f, std::sin(v));
            for (float side : {1.0f, -1.0f}) {
                const glm::vec3 at = glm::vec3(0, 0, 0.1f) + glm::vec3(side * 0.3f * d.x, 0.36f * d.y, 0.42f * d.z);
                Mesh curl = make_icosphere(0.05f, 2);
                for (glm::vec3& p : curl.positions) p += at;
                append(m, curl);
            }
        }
    for (glm::vec3& p : m.positions) p = {p.x, p.z, -p.y};  // z up -> y up, -y -> +z
    return m;
}

// A standing figure, z up: legs with flat soles at z = 0.1, a torso, arms
// and a round head; no flat base to speak of, but a clear long axis.
inline Mesh figure_z_up() {
    Mesh m;
    for (float x : {-0.12f, 0.12f}) append(m, ellipsoid_at({x, 0, 0.45f}, {0.08f, 0.1f, 0.45f}, 0.1f));
    append(m, ellipsoid_at({0, 0, 1.2f}, {0.25f, 0.14f, 0.38f}));
    for (float x : {-0.32f, 0.32f}) append(m, ellipsoid_at({x, 0, 1.15f}, {0.05f, 0.05f, 0.35f}));
    append(m, ellipsoid_at({0, 0, 1.68f}, {0.11f, 0.12f, 0.13f}));
    return m;
}

// The mesh with every position mapped by f.
inline Mesh mapped(Mesh m, const std::function<glm::vec3(glm::vec3)>& f) {
    for (glm::vec3& p : m.positions) p = f(p);
    return m;
}

}  // namespace kappa::test
