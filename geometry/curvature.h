// Curvature estimation of Rusinkiewicz 2004 ("Estimating curvatures and
// their derivatives on triangle meshes", 3DPVT), sections 3.1-3.3:
//  1. per face, a least-squares fit of the second fundamental tensor
//     II = [[e, f], [f, g]] in a frame (t, b) of the face plane, from the
//     differences of vertex normals along the three edges: II * e_j = dn_j;
//  2. per vertex, the tensors of its faces re-expressed in the vertex's
//     tangent frame, after rotating that frame into each face's plane
//     (sec. 3.3), and averaged with mixed-Voronoi corner-area weights;
//  3. diagonalisation into principal curvatures and directions.
// Step 1 runs per face, steps 2-3 per vertex: every output is written by one
// thread, in a fixed order, so results do not depend on the thread count.
#pragma once

#include "face_geometry.h"
#include "mesh.h"
#include "tensor_frames.h"
#include "vertex_faces.h"

#include <glm/vec3.hpp>
#include <vector>

namespace kappa {

// What the curvature step learns about each face; the derivative-of-curvature
// step reuses it.
struct FaceFits {
    // Orthonormal frame (t, b) in each face's plane, t along the edge from
    // corner 1 to corner 2, t x b the face normal.
    std::vector<glm::vec3> t, b;
    // The fitted second fundamental tensor in (t, b).
    std::vector<Tensor2> tensor;
    // 1 where the face is usable: not degenerate and its fit succeeded.
    std::vector<uint8_t> ok;
};

// Curvature tensor per vertex, in the vertex's tangent frame
// tangent_frame(normal) (frames are recomputed from the normals wherever
// needed rather than stored).
struct VertexTensors {
    std::vector<Tensor2> tensor;
};

// Steps 1 to 3 up to the averaged tensors. `normals` are unit length.
VertexTensors compute_curvature_tensors(const Mesh& mesh, const VertexFaces& vf,
                                        const std::vector<glm::vec3>& normals, const FaceGeometry& faces,
                                        FaceFits& fits);

// Diagonalisation: k1 >= k2 and the first principal direction d1.
void principal_curvatures(const VertexTensors& tensors, const std::vector<glm::vec3>& normals, std::vector<float>& k1,
                          std::vector<float>& k2, std::vector<glm::vec3>& d1);

// The second principal direction d2 = n x d1 (so d1 x d2 = n), as
// diagonalize_tensor gives it. Separate so that it can be allocated after the
// big temporaries of the derivative step are gone.
std::vector<glm::vec3> second_principal_directions(const std::vector<glm::vec3>& normals,
                                                   const std::vector<glm::vec3>& d1);

}  // namespace kappa
