#include "face_geometry.h"

#include "geometry/mesh/degenerate.h"
#include "geometry/parallel/double_lanes.h"
#include "geometry/io/prefault.h"
#include "geometry/parallel/parallel.h"
#include "voronoi_areas.h"

#include <cstring>

namespace kappa {

namespace {

// Faces first .. first + L - 1, L the lanes of D (double_lanes.h: four at
// once, two, or one), in double precision, stored as float into their
// records (phase 1 of face_record.h); all 0 but the vertex indices for a
// degenerate face (degenerate.h) or one whose edges are too short for
// float (< ~1e-19: 1 / |e|^2 overflows).
template <typename D>
KAPPA_LANES_INLINE void face_geometry(const Mesh& mesh, size_t first, FaceRecord* out) {
    using namespace lanes;
    using F = FloatsFor<D>;
    Vec3<D> p[3];
    F index_bits[3];  // the vertex indices' bits, as float lanes
    for (int c = 0; c < 3; ++c) {
        p[c] = widen3<D>(load3<D>([&](int j) { return &mesh.positions[mesh.faces[first + j][c]].x; }));
        if constexpr (kLanes<D> == 1) {
            std::memcpy(&index_bits[c], &mesh.faces[first][c], 4);
        } else {
            for (int j = 0; j < kLanes<D>; ++j) {  // through a float: clang takes no address of a lane
                float bits;
                std::memcpy(&bits, &mesh.faces[first + j][c], 4);
                index_bits[c][j] = bits;
            }
        }
    }
    const Vec3<D> e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};  // e[j] opposite corner j
    const Vec3<D> n = cross(e[2], p[2] - p[0]);                    // (p1 - p0) x (p2 - p0) = e2 x -e1
    const F il2[3] = {narrow<D>(1.0 / dot(e[0], e[0])), narrow<D>(1.0 / dot(e[1], e[1])),
                      narrow<D>(1.0 / dot(e[2], e[2]))};
    const F il2_sum = il2[0] + il2[1] + il2[2];
    const FloatMask<D> usable = narrow_mask<D>(nondegenerate_triangle<D>(e[0], e[1], e[2])) &
                                (il2_sum - il2_sum == 0.0f);  // finite
    const Vec3<D> corners = mixed_voronoi_corner_areas<D>(e, 0.5 * root(dot(n, n)));
    const F geometry[9] = {narrow<D>(n.x), narrow<D>(n.y), narrow<D>(n.z), il2[0], il2[1], il2[2],
                           narrow<D>(corners.x), narrow<D>(corners.y), narrow<D>(corners.z)};
    F record[16] = {};  // FaceRecord's 16 floats, phase 1
    for (int k = 0; k < 9; ++k) record[k] = keep<D>(usable, geometry[k]);
    for (int c = 0; c < 3; ++c) record[9 + c] = index_bits[c];  // every face keeps its vertex indices
    float* floats = reinterpret_cast<float*>(out);
    for (int k = 0; k < 16; k += 4) {
        const F block[4] = {record[k], record[k + 1], record[k + 2], record[k + 3]};
        store4<D>(block, floats + k);
    }
}

}  // namespace

FaceGeometry compute_face_geometry(const Mesh& mesh) {
    const size_t nf = mesh.face_count();
    FaceGeometry g;
    g.records = FaceRecords(nf);
    io::prefault(g.records.data(), nf * sizeof(FaceRecord));  // fresh memory: mapped by all threads at once
    parallel_for_chunks(nf, [&](size_t first, size_t last) {
        lanes::for_each_group(first, last, [&](auto lanes, size_t i) KAPPA_LANES_LAMBDA {
            face_geometry<decltype(lanes)>(mesh, i, &g.records[i]);
        });
    });
    return g;
}

}  // namespace kappa
