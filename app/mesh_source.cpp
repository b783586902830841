#include "mesh_source.h"

#include "geometry/mesh/default_model.h"
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/orientation.h"

namespace kappa::app {

Mesh load_mesh_or_default(const std::string& path) {
    return path.empty() ? make_default_model() : load_mesh(path);
}

DrawingPreparation prepare_for_drawing(Mesh& mesh) {
    DrawingPreparation p;
    p.units = drawing_units(mesh);
    to_drawing_units(mesh, p.units);
    p.turned_inside_out = is_inside_out(mesh);
    if (p.turned_inside_out) flip_faces(mesh);
    return p;
}

std::string mesh_display_name(const std::string& path) { return path.empty() ? "built-in model" : path; }

}  // namespace kappa::app
