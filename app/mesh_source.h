// Where a subcommand's mesh comes from: a file, or the built-in default model
// when no path is given (conventions.md).
#pragma once

#include "geometry/mesh/drawing_units.h"
#include "geometry/mesh/mesh.h"

#include <string>

namespace kappa::app {

// Loads `path` (throws kappa::MeshLoadError "PATH: problem"), or returns the
// built-in model when `path` is empty.
Mesh load_mesh_or_default(const std::string& path);

// A mesh made ready to be drawn (render, batch, Python, viewer; not `kappa
// curvature`): moved to drawing units (geometry/mesh/drawing_units.h) and, when
// its faces point inwards (geometry/mesh/orientation.h), turned round.
struct DrawingPreparation {
    DrawingUnits units;
    bool turned_inside_out = false;
};
DrawingPreparation prepare_for_drawing(Mesh& mesh);

// "built-in model" or the path, for messages.
std::string mesh_display_name(const std::string& path);

}  // namespace kappa::app
