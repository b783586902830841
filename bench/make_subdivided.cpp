// Makes big meshes for the scaling benchmark (bench/scaling.sh) and the GPU
// path's big mesh: each level splits every triangle into four at its edge
// midpoints (geometry/mesh/subdivide.h), so faces grow 4x and the surface
// stays the same.
//   make_subdivided MESH LEVELS OUT.ply   (binary little-endian PLY: x y z, vertex_indices)
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/subdivide.h"

#include <cstdio>
#include <cstdlib>

using namespace kappa;

namespace {

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
    for (int i = 0; i < std::atoi(argv[2]); ++i) mesh = subdivide_at_midpoints(mesh);
    if (!write_plain_ply(argv[3], mesh)) {
        std::fprintf(stderr, "make_subdivided: cannot write %s\n", argv[3]);
        return 1;
    }
    std::printf("%s: %zu vertices, %zu faces\n", argv[3], mesh.positions.size(), mesh.faces.size());
    return 0;
}
