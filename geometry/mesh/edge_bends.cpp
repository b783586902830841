#include "edge_bends.h"

#include "creases.h"
#include "edge_table.h"

#include "geometry/io/prefault.h"
#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace kappa {

namespace {

// Vertices per block: blocks, not threads, own the partial results, so the
// sums and the crease order do not depend on the thread count.
constexpr size_t kBlock = 16384;
// How many corners ahead the pass asks for faces and normals (about four vertices).
constexpr size_t kAhead = 24;

// The cosines the bends are compared with.
struct BendLimits {
    float cos_flat, cos_sharp, cos_limit;
    bool find;
    explicit BendLimits(float angle_deg)
        : cos_flat(std::cos(0.5f * float(M_PI) / 180.0f)), cos_sharp(std::cos(kAutoCreaseAngle * float(M_PI) / 180.0f)),
          cos_limit(std::cos(angle_deg * float(M_PI) / 180.0f)), find(angle_deg > 0) {}
};

// The edges (v, w), w > v, among the faces around v: counted into `out`, its
// creases appended. `normal(f)` gives face f's normal; `keys` is scratch.
template <typename NormalOf>
void bends_at(const Mesh& mesh, const VertexFaces& vf, size_t v, const BendLimits& limits, NormalOf&& normal,
              std::vector<uint64_t>& keys, EdgeBends& out) {
    const size_t nv = mesh.vertex_count();
    keys.clear();  // (w << 32 | face) for the faces around v with a corner w > v
    for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
        const uint32_t c = vf.corners[k], f = c / 3, i = c % 3;
        const Face& face = mesh.faces[f];
        if (!is_valid_face(face, nv)) continue;
        for (const uint32_t w : {face[(i + 1) % 3], face[(i + 2) % 3]})
            if (w > v) keys.push_back(uint64_t(w) << 32 | f);
    }
    // By w, then face: each edge's faces in face order, as in the edge table.
    sort_short_run(keys.data(), keys.data() + keys.size());
    for (size_t i = 0; i < keys.size();) {
        size_t j = i + 1;
        while (j < keys.size() && keys[j] >> 32 == keys[i] >> 32) ++j;
        if (j - i == 2) {
            const uint32_t fa = uint32_t(keys[i]), fb = uint32_t(keys[i + 1]);
            const glm::vec3 a = normal(fa), b = normal(fb);
            if (a != glm::vec3(0.0f) && b != glm::vec3(0.0f)) {  // degenerate faces have no angle
                const float d = glm::dot(a, b);
                ++out.interior;
                out.between += d < limits.cos_flat && d >= limits.cos_sharp;
                if (limits.find && d < limits.cos_limit) {
                    out.creases.push_back({uint32_t(v), uint32_t(keys[i] >> 32)});
                    out.crease_faces.push_back({fa, fb});
                }
            }
        }
        i = j;
    }
}

// Calls item(i, keys, out) for i in [0, n) in blocks of `block` items, each
// block with its own EdgeBends (blocks, not threads, own the partial results,
// so the sums and the crease order do not depend on the thread count), then
// joins the blocks' results in order: the creases come out sorted.
template <typename Item>
EdgeBends in_blocks(size_t n, size_t block, Item&& item) {
    const size_t blocks = (n + block - 1) / block;
    std::vector<EdgeBends> partial(blocks);
    parallel_for_chunks(
        blocks,
        [&](size_t first, size_t last) {
            std::vector<uint64_t> keys;  // scratch of bends_at
            for (size_t b = first; b < last; ++b)
                for (size_t i = b * block; i < std::min(n, (b + 1) * block); ++i) item(i, keys, partial[b]);
        },
        1);
    EdgeBends all;
    for (const EdgeBends& p : partial) {
        all.interior += p.interior;
        all.between += p.between;
        all.creases.insert(all.creases.end(), p.creases.begin(), p.creases.end());
        all.crease_faces.insert(all.crease_faces.end(), p.crease_faces.begin(), p.crease_faces.end());
    }
    return all;
}

}  // namespace

std::vector<glm::vec3> face_normals(const Mesh& mesh) {
    std::vector<glm::vec3> normals;
    io::reserve_prefaulted(normals, mesh.face_count());
    normals.resize(mesh.face_count());
    parallel_for(mesh.face_count(), [&](size_t f) {
        normals[f] = is_valid_face(mesh.faces[f], mesh.vertex_count()) ? face_normal(mesh, mesh.faces[f])
                                                                         : glm::vec3(0.0f);
    });
    return normals;
}

EdgeBends measure_edge_bends(const Mesh& mesh, const VertexFaces& vf, float angle_deg) {
    const size_t nv = mesh.vertex_count();
    const std::vector<glm::vec3> normals = face_normals(mesh);
    const BendLimits limits(angle_deg);
    return in_blocks(nv, kBlock, [&](size_t v, std::vector<uint64_t>& keys, EdgeBends& out) {
        // The faces around a vertex lie anywhere in the mesh: fetch those of the vertex a few
        // ahead now, or every face and normal read waits for memory.
        for (uint32_t k = vf.begin(v) + kAhead; k < vf.end(v) + kAhead && k < vf.corners.size(); ++k) {
            __builtin_prefetch(&mesh.faces[vf.corners[k] / 3]);
            __builtin_prefetch(&normals[vf.corners[k] / 3]);
        }
        bends_at(mesh, vf, v, limits, [&](uint32_t f) { return normals[f]; }, keys, out);
    });
}

EdgeBends measure_edge_bends_at(const Mesh& mesh, const VertexFaces& vf, float angle_deg,
                                const std::vector<uint32_t>& vertices, std::vector<glm::uvec2>* per_vertex) {
    const BendLimits limits(angle_deg);
    const auto normal = [&](uint32_t f) { return face_normal(mesh, mesh.faces[f]); };  // valid faces only
    constexpr size_t kListBlock = 1024;
    if (per_vertex) per_vertex->assign(vertices.size(), glm::uvec2(0));
    return in_blocks(vertices.size(), kListBlock, [&](size_t i, std::vector<uint64_t>& keys, EdgeBends& out) {
        const size_t interior = out.interior, between = out.between;
        bends_at(mesh, vf, vertices[i], limits, normal, keys, out);
        if (per_vertex) (*per_vertex)[i] = {uint32_t(out.interior - interior), uint32_t(out.between - between)};
    });
}

}  // namespace kappa
