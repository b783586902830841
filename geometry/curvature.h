// Curvature estimation of Rusinkiewicz 2004 ("Estimating curvatures and
// their derivatives on triangle meshes", 3DPVT), sections 3.1-3.3:
//  1. per face, a least-squares fit of the second fundamental tensor
//     II = [[e, f], [f, g]] in a frame (t, b) of the face plane, from the
//     differences of vertex normals along the three edges: II * e_j = dn_j;
//  2. per face corner, that tensor re-expressed in the corner vertex's
//     tangent frame, rotated into the face plane first (sec. 3.3);
//  3. per vertex, the corner tensors averaged with mixed-Voronoi corner-area
//     weights, then diagonalised into principal curvatures and directions.
// Steps 1-2 run per face, step 3 per vertex: every output is written by one
// thread, so results do not depend on the thread count.
#pragma once

#include "face_geometry.h"
#include "mesh.h"
#include "tensor_frames.h"
#include "vertex_faces.h"

#include <glm/vec3.hpp>
#include <vector>

namespace kappa {

// What the curvature step learns about each face and corner; the
// derivative-of-curvature step reuses it.
struct FaceFits {
    // Orthonormal frame (t, b) in each face's plane, t along the edge from
    // corner 1 to corner 2, t x b the face normal; zero for degenerate faces.
    std::vector<glm::vec3> t, b;
    // Per corner (3 f + j): the corner vertex's tangent frame (u, v),
    // rotated into the face plane, in (t, b) coordinates.
    std::vector<FrameChange> corner_frames;
    // Per corner: its mixed-Voronoi area, or 0 where the face is unusable
    // (degenerate, or its fit failed).
    std::vector<float> corner_weights;
};

// Curvature tensor per vertex, in the tangent frame (u, v) = tangent_frame(n).
struct VertexTensors {
    std::vector<glm::vec3> u, v;
    std::vector<Tensor2> tensor;
};

// Steps 1 to 3 up to the averaged tensors. `normals` are unit length.
VertexTensors compute_curvature_tensors(const Mesh& mesh, const VertexFaces& vf,
                                        const std::vector<glm::vec3>& normals, const FaceGeometry& faces,
                                        FaceFits& fits);

// Diagonalisation: k1 >= k2, d1 x d2 = n = u x v.
void principal_curvatures(const VertexTensors& tensors, std::vector<float>& k1, std::vector<float>& k2,
                          std::vector<glm::vec3>& d1, std::vector<glm::vec3>& d2);

}  // namespace kappa
