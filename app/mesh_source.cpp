#include "mesh_source.h"

#include "geometry/default_model.h"
#include "geometry/io/mesh_io.h"

namespace kappa::app {

Mesh load_mesh_or_default(const std::string& path) {
    return path.empty() ? make_default_model() : load_mesh(path);
}

std::string mesh_display_name(const std::string& path) { return path.empty() ? "built-in model" : path; }

}  // namespace kappa::app
