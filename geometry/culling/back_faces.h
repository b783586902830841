// Where the back faces of a mesh can be seen, so a renderer may cull them
// elsewhere (half the triangles of a frame, and a software rasteriser's
// time goes mostly to setting up triangles).
//
// Argument: cap every hole (a boundary component) with a surface spanning its
// boundary vertices. If every edge is used at most once in each direction
// (consistent winding, no edge with three faces) and the normals point
// outside (geometry/mesh/orientation.h), the capped surface bounds a solid, and a
// ray from an eye outside the mesh's bounding sphere enters it through a
// front-facing face. So the first face a ray meets is front-facing unless
// the ray passes through a cap: back faces need drawing only inside the
// screen rectangle of each hole's vertices (the fan of triangles over a
// hole's vertices projects inside it). Surfaces that pass through
// themselves inside out could break this; none of the meshes we meet do.
//
// Boundary policy: a mesh with an edge of three or more faces, an edge used
// twice in one direction, or no clear outward orientation is not cullable.
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"

#include <glm/vec3.hpp>

#include <vector>

namespace kappa {

struct BackFaceVisibility {
    bool cullable = false;                      // the conditions above hold
    std::vector<std::vector<glm::vec3>> holes;  // per boundary component, its vertices' positions
};

BackFaceVisibility back_face_visibility(const Mesh& mesh);
// The same from the mesh's vertex-face rows (build_vertex_faces) and whether its normals point
// clearly outside (is_outside_out, or known from an earlier pass over the faces): a pass over
// the rows, the vertices in parallel.
BackFaceVisibility back_face_visibility(const Mesh& mesh, const VertexFaces& vf, bool outside_out);

}  // namespace kappa
