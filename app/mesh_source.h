// Where a subcommand's mesh comes from: a file, or the built-in default model
// when no path is given (conventions.md).
#pragma once

#include "geometry/mesh.h"

#include <string>

namespace kappa::app {

// Loads `path` (throws kappa::MeshLoadError "PATH: problem"), or returns the
// built-in model when `path` is empty.
Mesh load_mesh_or_default(const std::string& path);

// "built-in model" or the path, for messages.
std::string mesh_display_name(const std::string& path);

}  // namespace kappa::app
