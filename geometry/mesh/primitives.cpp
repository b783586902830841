#include "primitives.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <map>
#include <random>
#include <utility>

namespace kappa {

namespace {

Mesh icosahedron() {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    Mesh m;
    m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    m.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
               {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (auto& p : m.positions) p = glm::normalize(p);
    return m;
}

// Splits each triangle into four, new vertices at edge midpoints pushed to the unit sphere.
void subdivide_on_unit_sphere(Mesh& m) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint;
    auto mid = [&](uint32_t a, uint32_t b) {
        auto key = std::make_pair(std::min(a, b), std::max(a, b));
        auto it = midpoint.find(key);
        if (it != midpoint.end()) return it->second;
        uint32_t idx = uint32_t(m.positions.size());
        m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
        midpoint.emplace(key, idx);
        return idx;
    };
    std::vector<Face> faces;
    faces.reserve(m.faces.size() * 4);
    for (const Face& f : m.faces) {
        uint32_t a = mid(f[0], f[1]), b = mid(f[1], f[2]), c = mid(f[2], f[0]);
        faces.push_back({f[0], a, c});
        faces.push_back({f[1], b, a});
        faces.push_back({f[2], c, b});
        faces.push_back({a, b, c});
    }
    m.faces = std::move(faces);
}

}  // namespace

Mesh make_icosphere(float radius, int levels) {
    Mesh m = icosahedron();
    for (int i = 0; i < levels; ++i) subdivide_on_unit_sphere(m);
    for (auto& p : m.positions) p *= radius;
    return m;
}

Mesh make_uv_sphere(float radius, int rings, int segments) {
    Mesh m;
    const float pi = glm::pi<float>();
    m.positions.push_back({0, 0, radius});
    for (int i = 1; i < rings; ++i) {
        float theta = pi * float(i) / float(rings);
        for (int j = 0; j < segments; ++j) {
            float phi = 2 * pi * float(j) / float(segments);
            m.positions.push_back(radius * glm::vec3(std::sin(theta) * std::cos(phi),
                                                     std::sin(theta) * std::sin(phi), std::cos(theta)));
        }
    }
    m.positions.push_back({0, 0, -radius});
    const uint32_t south = uint32_t(m.positions.size() - 1);
    auto ring = [&](int i, int j) { return uint32_t(1 + (i - 1) * segments + (j % segments)); };
    for (int j = 0; j < segments; ++j) m.faces.push_back({0, ring(1, j), ring(1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            m.faces.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            m.faces.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
    for (int j = 0; j < segments; ++j) m.faces.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
    return m;
}

Mesh make_torus(float R, float r, int nu, int nv) {
    Mesh m;
    const float pi = glm::pi<float>();
    for (int i = 0; i < nu; ++i) {
        float u = 2 * pi * float(i) / float(nu);
        for (int j = 0; j < nv; ++j) {
            float v = 2 * pi * float(j) / float(nv);
            float rho = R + r * std::cos(v);
            m.positions.push_back({rho * std::cos(u), rho * std::sin(u), r * std::sin(v)});
        }
    }
    auto idx = [&](int i, int j) { return uint32_t((i % nu) * nv + (j % nv)); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            m.faces.push_back({idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)});
            m.faces.push_back({idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)});
        }
    return m;
}

Mesh make_ellipsoid(float a, float b, float c, int levels) {
    Mesh m = make_icosphere(1.0f, levels);
    for (auto& p : m.positions) p *= glm::vec3(a, b, c);
    return m;
}

Mesh make_grid(float size, int n) {
    Mesh m;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            m.positions.push_back({size * (float(j) / n - 0.5f), size * (float(i) / n - 0.5f), 0.0f});
    auto idx = [&](int i, int j) { return uint32_t(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            m.faces.push_back({idx(i, j), idx(i, j + 1), idx(i + 1, j + 1)});
            m.faces.push_back({idx(i, j), idx(i + 1, j + 1), idx(i + 1, j)});
        }
    return m;
}

Mesh make_jittered_sphere(float radius, int levels, float jitter, uint32_t seed) {
    Mesh m = make_icosphere(1.0f, levels);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    // Shortest edge of the subdivided icosahedron on the unit sphere is about 0.9 / 2^levels;
    // moving each vertex by at most jitter times half of it keeps every triangle unfolded
    // for jitter < 1.
    const float step = 0.45f / float(1 << levels);
    for (auto& p : m.positions) {
        glm::vec3 d;
        do d = glm::vec3(u(rng), u(rng), u(rng));
        while (glm::dot(d, d) > 1.0f);
        d -= glm::dot(d, p) * p;  // tangential
        p = glm::normalize(p + jitter * step * d) * radius;
    }
    return m;
}

void add_normal_noise(Mesh& mesh, float sigma, uint32_t seed) {
    std::vector<glm::vec3> normals(mesh.vertex_count(), glm::vec3(0.0f));
    for (const Face& f : mesh.faces) {
        const glm::vec3 an =
            glm::cross(mesh.positions[f[1]] - mesh.positions[f[0]], mesh.positions[f[2]] - mesh.positions[f[0]]);
        for (int k = 0; k < 3; ++k) normals[f[k]] += an;
    }
    std::mt19937 rng(seed);
    // Uniform in (0, 1] from 32 random bits, then Box-Muller (one Gaussian per pair).
    auto uniform = [&] { return (double(rng()) + 1.0) / 4294967296.0; };
    const double two_pi = 2.0 * glm::pi<double>();
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
        const double g = std::sqrt(-2.0 * std::log(uniform())) * std::cos(two_pi * uniform());
        const float len = glm::length(normals[i]);
        if (len > 0) mesh.positions[i] += float(sigma * g) * (normals[i] / len);
    }
}

}  // namespace kappa
