// Small meshes written out by hand for tests.
#pragma once

#include "geometry/mesh/mesh.h"

#include <cstdint>
#include <fstream>
#include <string>

namespace kappa::test {

// The unit cube [0, 1]^3: 8 vertices, two triangles a face, counter-clockwise
// from outside (faces -x, +x, -y, +y, -z, +z).
inline Mesh unit_cube() {
    Mesh m;
    for (int i = 0; i < 8; ++i) m.positions.push_back({float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)});
    const Face faces[] = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                          {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
    for (const Face& f : faces) m.faces.push_back(f);
    return m;
}

// An axis-aligned box from lo to hi (the unit cube scaled and moved).
inline Mesh box(glm::vec3 lo, glm::vec3 hi) {
    Mesh m = unit_cube();
    for (glm::vec3& p : m.positions) p = lo + p * (hi - lo);
    return m;
}

// The faces of b appended to a (a union of separate pieces).
inline void append(Mesh& a, const Mesh& b) {
    const uint32_t base = uint32_t(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (Face f : b.faces) a.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
}

// Writes m as an OFF file (coordinates to 9 digits: float32 round-trips).
inline void write_off(const std::string& path, const Mesh& m) {
    std::ofstream f(path);
    f.precision(9);
    f << "OFF\n" << m.positions.size() << " " << m.faces.size() << " 0\n";
    for (const auto& p : m.positions) f << p.x << " " << p.y << " " << p.z << "\n";
    for (const auto& t : m.faces) f << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

}  // namespace kappa::test
