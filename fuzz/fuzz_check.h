// Shared body of the fuzz targets: a reader must either return a valid mesh
// or throw MeshLoadError. Anything else (another exception, a crash, a
// sanitizer report, an invalid mesh) is a bug that libFuzzer reports.
#pragma once

#include "geometry/io/mesh_io.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace kappa::fuzz {

template <typename Reader>
int check_reader(const uint8_t* data, size_t size, Reader&& read) {
    Mesh mesh;
    try {
        mesh = read(reinterpret_cast<const char*>(data), size);
    } catch (const MeshLoadError&) {
        return 0;
    }
    // Invariants of every successfully loaded mesh.
    auto invalid = [](const char* what) {
        std::fprintf(stderr, "invalid mesh returned: %s\n", what);
        std::abort();
    };
    if (mesh.positions.empty()) invalid("no vertices");
    for (const glm::vec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) invalid("non-finite position");
    for (const Face& f : mesh.faces)
        if (f.x >= mesh.vertex_count() || f.y >= mesh.vertex_count() || f.z >= mesh.vertex_count())
            invalid("face index out of range");
    return 0;
}

}  // namespace kappa::fuzz
