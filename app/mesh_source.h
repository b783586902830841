// Where a subcommand's mesh comes from: a file, or the built-in default model
// when no path is given (conventions.md).
#pragma once

#include "geometry/mesh/creases.h"
#include "geometry/mesh/drawing_units.h"
#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"

#include <string>

namespace kappa::app {

// Loads `path` (throws kappa::MeshLoadError "PATH: problem"), or returns the
// built-in model when `path` is empty.
Mesh load_mesh_or_default(const std::string& path);

// A mesh made ready to be drawn (render, batch, Python, viewer; not `kappa
// curvature`): moved to drawing units (geometry/mesh/drawing_units.h), turned
// round when its faces point inwards (geometry/mesh/orientation.h; `vf`, the
// mesh's vertex-face rows, made the turned mesh's), and its creases found at
// the angle `crease_setting` resolves to (geometry/mesh/creases.h). Costs
// one pass over the faces (geometry/mesh/face_survey.h) and a look at a sample
// of the vertices and at those where an edge may be sharp, unless the
// sample cannot tell `auto`'s angle (then one more pass over every edge).
struct DrawingPreparation {
    DrawingUnits units;
    bool turned_inside_out = false;
    bool outside_out = false;  // after the turn: the normals point clearly outside (back faces may be culled)
    ResolvedCreases creases;
    PositionBounds box;  // of the mesh as prepared (in drawing units); the split, which copies vertices, keeps it
};
DrawingPreparation prepare_for_drawing(Mesh& mesh, VertexFaces& vf, float crease_setting);

// "built-in model" or the path, for messages.
std::string mesh_display_name(const std::string& path);

}  // namespace kappa::app
