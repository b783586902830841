#include "default_model.h"

#include "primitives.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

// Radial displacement features on the unit sphere, for a unit direction d.
// A round bump: amplitude * exp((d.c - 1) / width^2), a smooth function of
// the chord distance |d - c|^2 = 2 - 2 d.c (a von Mises-Fisher profile),
// about a Gaussian of width `width` radians near its centre.
struct Bump {
    glm::vec3 centre;
    float width;
    float amplitude;  // > 0 bulges out (convex), < 0 dents in (concave)
};

// An elongated bump along the great circle through `centre` perpendicular
// to `axis`: Gaussian of width `width` across the circle (distance d.axis),
// round window of width `length` along it.
struct Ridge {
    glm::vec3 centre, axis;
    float width, length, amplitude;  // amplitude < 0: a valley
};

float bump(const Bump& b, glm::vec3 d) {
    const glm::vec3 c = glm::normalize(b.centre);
    return b.amplitude * std::exp((glm::dot(d, c) - 1.0f) / (b.width * b.width));
}

float ridge(const Ridge& r, glm::vec3 d) {
    const glm::vec3 c = glm::normalize(r.centre);
    // Make the axis exactly perpendicular to the centre.
    const glm::vec3 n = glm::normalize(r.axis - glm::dot(r.axis, c) * c);
    const float across = glm::dot(d, n);
    return r.amplitude * std::exp(-0.5f * across * across / (r.width * r.width)) *
           std::exp((glm::dot(d, c) - 1.0f) / (r.length * r.length));
}

// The camera of the default view looks from +z, so most small features sit
// on the +z half, several near the silhouette where they are seen obliquely.
const Bump kBumps[] = {
    {{0.50f, 0.60f, 0.60f}, 0.26f, 0.45f},     // protruding lobe, upper right: overlaps the body
    {{-0.60f, -0.45f, 0.20f}, 0.55f, 0.20f},   // broad bulge, lower left
    {{0.20f, -0.30f, 0.93f}, 0.20f, -0.17f},   // dent in the middle of the view
    {{-0.55f, 0.30f, 0.78f}, 0.16f, -0.14f},   // dent towards the left silhouette
    {{0.85f, -0.25f, 0.45f}, 0.14f, -0.11f},   // dent near the right silhouette
    {{0.00f, -0.20f, -1.00f}, 0.35f, -0.15f},  // wide hollow on the back
    // A ring of small alternating bumps and dents: saddles between them.
    {{-0.62f, 0.62f, 0.20f}, 0.12f, 0.08f},
    {{-0.45f, 0.80f, 0.05f}, 0.12f, -0.08f},
    {{-0.25f, 0.92f, 0.15f}, 0.12f, 0.08f},
    {{-0.30f, 0.85f, 0.40f}, 0.12f, -0.08f},
    {{-0.52f, 0.70f, 0.45f}, 0.12f, 0.08f},
};

const Ridge kRidges[] = {
    {{-0.20f, -0.75f, 0.60f}, {0.30f, -0.40f, -0.20f}, 0.09f, 0.55f, 0.12f},  // ridge, lower front
    {{-0.15f, 0.05f, 0.99f}, {1.00f, 0.50f, 0.00f}, 0.10f, 0.45f, -0.11f},    // valley across the front
};

}  // namespace

Mesh make_default_model() { return make_default_model_from(make_icosphere(1.0f, 6)); }

Mesh make_default_model_from(Mesh mesh) {
    const glm::vec3 stretch(1.2f, 1.0f, 0.9f);
    for (glm::vec3& p : mesh.positions) {
        const glm::vec3 d = glm::normalize(p);
        float r = 1.0f;
        for (const Bump& b : kBumps) r += bump(b, d);
        for (const Ridge& rg : kRidges) r += ridge(rg, d);
        p = stretch * (r * d);
    }
    // Centre the bounding box at the origin, farthest vertex at distance 1.
    glm::vec3 lo = mesh.positions[0], hi = lo;
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 centre = 0.5f * (lo + hi);
    float radius = 0.0f;
    for (glm::vec3& p : mesh.positions) {
        p -= centre;
        radius = std::max(radius, glm::length(p));
    }
    for (glm::vec3& p : mesh.positions) p /= radius;
    return mesh;
}

}  // namespace kappa
