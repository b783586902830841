#include "face_geometry.h"

#include "degenerate.h"
#include "double_lanes.h"
#include "io/prefault.h"
#include "parallel.h"
#include "voronoi_areas.h"

namespace kappa {

namespace {

// Faces first .. first + L - 1, L the lanes of D (double_lanes.h: four at
// once, two, or one), in double precision, stored as float; all 0 for a
// degenerate face (degenerate.h) or one whose edges are too short for
// float (< ~1e-19: 1 / |e|^2 overflows).
template <typename D>
KAPPA_LANES_INLINE void face_geometry(const Mesh& mesh, size_t first, FaceGeometry& g) {
    using namespace lanes;
    using F = FloatsFor<D>;
    Vec3<D> p[3];
    for (int c = 0; c < 3; ++c)
        p[c] = widen3<D>(load3<D>([&](int j) { return &mesh.positions[mesh.faces[first + j][c]].x; }));
    const Vec3<D> e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};  // e[j] opposite corner j
    const Vec3<D> n = cross(e[2], p[2] - p[0]);                    // (p1 - p0) x (p2 - p0) = e2 x -e1
    const Vec3<F> il2 = {narrow<D>(1.0 / dot(e[0], e[0])), narrow<D>(1.0 / dot(e[1], e[1])),
                         narrow<D>(1.0 / dot(e[2], e[2]))};
    const F il2_sum = il2.x + il2.y + il2.z;
    const FloatMask<D> usable = narrow_mask<D>(nondegenerate_triangle<D>(e[0], e[1], e[2])) &
                                (il2_sum - il2_sum == 0.0f);  // finite
    const Vec3<D> corners = mixed_voronoi_corner_areas<D>(e, 0.5 * root(dot(n, n)));
    const auto kept = [&](const Vec3<F>& v) {
        return Vec3<F>{keep<D>(usable, v.x), keep<D>(usable, v.y), keep<D>(usable, v.z)};
    };
    store3<D>(kept({narrow<D>(n.x), narrow<D>(n.y), narrow<D>(n.z)}), &g.area_normals[first].x);
    store3<D>(kept(il2), &g.inv_edge_len2[first].x);
    store3<D>(kept({narrow<D>(corners.x), narrow<D>(corners.y), narrow<D>(corners.z)}), &g.corner_areas[first].x);
}

}  // namespace

FaceGeometry compute_face_geometry(const Mesh& mesh) {
    const size_t nf = mesh.face_count();
    FaceGeometry g;
    for (auto* v : {&g.area_normals, &g.inv_edge_len2, &g.corner_areas}) {
        io::reserve_prefaulted(*v, nf);  // fresh memory: mapped by all threads at once
        v->resize(nf);
    }
    parallel_for_ranges(nf, [&](size_t first, size_t last) {
        lanes::for_each_group(first, last, [&](auto lanes, size_t i) KAPPA_LANES_LAMBDA {
            face_geometry<decltype(lanes)>(mesh, i, g);
        });
    });
    return g;
}

}  // namespace kappa
