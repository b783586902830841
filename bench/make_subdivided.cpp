// Makes big meshes for the scaling benchmark (bench/scaling.sh): each
// subdivision splits every triangle into four at its edge midpoints (shared
// midpoints made once), so faces grow 4x and the surface stays the same.
//   make_subdivided MESH LEVELS OUT.ply   (binary little-endian PLY: x y z, vertex_indices)
#include "geometry/io/mesh_io.h"

#include <cstdio>
#include <cstdlib>
#include <unordered_map>

using namespace kappa;

namespace {

Mesh subdivide(const Mesh& in) {
    Mesh out;
    out.positions = in.positions;
    out.faces.reserve(in.faces.size() * 4);
    std::unordered_map<uint64_t, uint32_t> midpoint;
    midpoint.reserve(in.faces.size() * 2);
    auto mid = [&](uint32_t a, uint32_t b) {
        const uint64_t key = uint64_t(std::min(a, b)) << 32 | std::max(a, b);
        const auto [it, fresh] = midpoint.emplace(key, uint32_t(out.positions.size()));
        if (fresh) out.positions.push_back(0.5f * (in.positions[a] + in.positions[b]));
        return it->second;
    };
    for (const Face& f : in.faces) {
        const uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
        out.faces.push_back({f[0], ab, ca});
        out.faces.push_back({ab, f[1], bc});
        out.faces.push_back({ca, bc, f[2]});
        out.faces.push_back({ab, bc, ca});
    }
    return out;
}

bool write_plain_ply(const char* path, const Mesh& m) {
    FILE* f = std::fopen(path, "wb");
    if (!f) return false;
    std::fprintf(f, "ply\nformat binary_little_endian 1.0\nelement vertex %zu\nproperty float x\nproperty float y\n"
                    "property float z\nelement face %zu\nproperty list uchar int vertex_indices\nend_header\n",
                 m.positions.size(), m.faces.size());
    std::fwrite(m.positions.data(), sizeof(glm::vec3), m.positions.size(), f);
    for (const Face& t : m.faces) {
        const unsigned char n = 3;
        const int32_t idx[3] = {int32_t(t[0]), int32_t(t[1]), int32_t(t[2])};
        std::fwrite(&n, 1, 1, f);
        std::fwrite(idx, 4, 3, f);
    }
    return std::fclose(f) == 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: make_subdivided MESH LEVELS OUT.ply\n");
        return 2;
    }
    Mesh mesh = load_mesh(argv[1]);
    for (int i = 0; i < std::atoi(argv[2]); ++i) mesh = subdivide(mesh);
    if (!write_plain_ply(argv[3], mesh)) {
        std::fprintf(stderr, "make_subdivided: cannot write %s\n", argv[3]);
        return 1;
    }
    std::printf("%s: %zu vertices, %zu faces\n", argv[3], mesh.positions.size(), mesh.faces.size());
    return 0;
}
