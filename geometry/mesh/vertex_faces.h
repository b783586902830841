// Vertex -> incident face corners, in compressed rows (CSR). Corner c is
// face c / 3, local index c % 3. Rows list corners in increasing face order,
// so every per-vertex gather over them is deterministic.
#pragma once

#include "mesh.h"

#include <cstdint>
#include <vector>

namespace kappa {

struct VertexFaces {
    std::vector<uint32_t> offsets;  // size V + 1
    std::vector<uint32_t> corners;  // size 3 F

    uint32_t begin(size_t v) const { return offsets[v]; }
    uint32_t end(size_t v) const { return offsets[v + 1]; }
    uint32_t degree(size_t v) const { return offsets[v + 1] - offsets[v]; }
};

// Counting sort over the face corners: O(V + F).
VertexFaces build_vertex_faces(const Mesh& mesh);

}  // namespace kappa
