// Curvature estimation of Rusinkiewicz 2004 ("Estimating curvatures and
// their derivatives on triangle meshes", 3DPVT), sections 3.1-3.3:
//  1. per face, a least-squares fit of the second fundamental tensor
//     II = [[e, f], [f, g]] in a frame (t, b) of the face plane, from the
//     differences of vertex normals along the three edges: II * e_j = dn_j;
//  2. per vertex, the face tensors rotated into the vertex's tangent frame
//     and averaged with mixed-Voronoi corner-area weights;
//  3. principal curvatures and directions by diagonalisation.
#pragma once

#include "mesh.h"
#include "tensor_frames.h"
#include "vertex_faces.h"

#include <glm/vec3.hpp>
#include <vector>

namespace kappa {

// Orthonormal frame (t, b) in each face's plane, t along the edge from
// corner 1 to corner 2, t x b the face normal. Degenerate faces get t = b = 0.
struct FaceFrames {
    std::vector<glm::vec3> t, b;
    bool degenerate(size_t f) const { return t[f] == glm::vec3(0.0f); }
};
FaceFrames compute_face_frames(const Mesh& mesh);

// Curvature tensor per vertex, in the tangent frame (u, v), u x v = normal.
struct VertexTensors {
    std::vector<glm::vec3> u, v;
    std::vector<Tensor2> tensor;
};

// Steps 1 and 2. `normals` must be unit length (or zero for vertices that
// have no valid face), `corner_areas` from compute_corner_areas.
VertexTensors compute_curvature_tensors(const Mesh& mesh, const VertexFaces& vf, const FaceFrames& frames,
                                        const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec3>& corner_areas);

// Step 3: k1 >= k2, d1 x d2 = n = u x v.
void principal_curvatures(const VertexTensors& tensors, std::vector<float>& k1, std::vector<float>& k2, std::vector<glm::vec3>& d1,
                          std::vector<glm::vec3>& d2);

}  // namespace kappa
