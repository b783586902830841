// Small meshes written out by hand for tests.
#pragma once

#include "geometry/mesh.h"

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

}  // namespace kappa::test
