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
#include "face_record.h"
#include "geometry/mesh/mesh.h"
#include "geometry/parallel/prefetch.h"
#include "tensor_frames.h"
#include "geometry/parallel/uninitialized_array.h"
#include "geometry/mesh/vertex_faces.h"

#include <glm/vec3.hpp>
#include <cstddef>
#include <cstring>
#include <vector>

namespace kappa {

// Adds w * turned(fit, rotation) to `sum` over vertex v's usable faces, w the
// corner's weight and rotation its frame rotation, in face order; returns
// the sum of the weights. The gather of both vertex steps; `turned` gives
// four float lanes (tensor_frames.h's turn_*_harmonics).
template <typename Turned>
float add_face_values(const VertexFaces& vf, const FaceRecords& fits, size_t v, lanes::Lanes& sum, const Turned& turned) {
    float wsum = 0;
    for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
        const uint32_t c = vf.corners[k];
        prefetch_face_ahead(vf, k, fits.data());
        const FaceRecord& fit = fits[c / 3];
        const float w = fit.weights[c % 3];
        if (!(w > 0)) continue;
        lanes::Lanes values;
        std::memcpy(&values, fit.fit, sizeof values);
        sum += w * turned(values, fit.corners[c % 3]);
        wsum += w;
    }
    return wsum;
}

// Curvature tensor per vertex, in the vertex's tangent frame
// tangent_frame(normal) (frames are recomputed from the normals wherever
// needed rather than stored).
struct VertexTensors {
    std::vector<Tensor2> tensor;
};

// Steps 1 to 3 up to the averaged tensors. `normals` are unit length;
// `records` hold the faces' geometry on entry (compute_face_geometry) and
// their fits on return (face_record.h: phase 2), for compute_dcurv.
VertexTensors compute_curvature_tensors(const Mesh& mesh, const VertexFaces& vf,
                                        const std::vector<glm::vec3>& normals, FaceRecords& records);

// Diagonalisation: k1 >= k2 and the first principal direction d1.
void principal_curvatures(const VertexTensors& tensors, const std::vector<glm::vec3>& normals, std::vector<float>& k1,
                          std::vector<float>& k2, std::vector<glm::vec3>& d1);

// The second principal direction d2 = n x d1 (so d1 x d2 = n), as
// diagonalize_tensor gives it. Separate so that it can be allocated after the
// big temporaries of the derivative step are gone.
std::vector<glm::vec3> second_principal_directions(const std::vector<glm::vec3>& normals,
                                                   const std::vector<glm::vec3>& d1);

}  // namespace kappa
