#include "vertex_faces.h"

namespace kappa {

VertexFaces build_vertex_faces(const Mesh& mesh) {
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    VertexFaces vf;
    vf.offsets.assign(nv + 1, 0);
    for (const Face& f : mesh.faces)
        for (int j = 0; j < 3; ++j) ++vf.offsets[f[j] + 1];
    for (size_t v = 0; v < nv; ++v) vf.offsets[v + 1] += vf.offsets[v];
    vf.corners.resize(3 * nf);
    std::vector<uint32_t> fill(vf.offsets.begin(), vf.offsets.end() - 1);
    for (size_t f = 0; f < nf; ++f)
        for (int j = 0; j < 3; ++j) vf.corners[fill[mesh.faces[f][j]]++] = uint32_t(3 * f + j);
    return vf;
}

}  // namespace kappa
