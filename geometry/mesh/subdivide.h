// Midpoint subdivision: every triangle split into four at its edges'
// midpoints (each midpoint made once, shared by the faces of its edge), so
// faces grow 4x and the surface stays the same, point for point. Makes big
// test and benchmark meshes from small ones (bench/make_subdivided.cpp, the
// web page's sliced preparation in tests/test_web_page.cpp).
//
// The input's vertices keep their numbers; the midpoints follow, in order of
// first use by the faces. Face f's four children are faces 4f .. 4f + 3:
// (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca), the same winding.
#pragma once

#include "mesh.h"

namespace kappa {

Mesh subdivide_at_midpoints(const Mesh& mesh);

}  // namespace kappa
