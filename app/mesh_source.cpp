#include "mesh_source.h"

#include "geometry/mesh/default_model.h"
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/face_survey.h"
#include "geometry/mesh/orientation.h"

namespace kappa::app {

Mesh load_mesh_or_default(const std::string& path) {
    return path.empty() ? make_default_model() : load_mesh(path);
}

DrawingPreparation prepare_for_drawing(Mesh& mesh, VertexFaces& vf, float crease_setting) {
    DrawingPreparation p;
    p.box = position_bounds(mesh.positions);
    p.units = drawing_units(p.box);
    if (!p.units.identity()) {
        to_drawing_units(mesh, p.units);
        p.box = position_bounds(mesh.positions);
    }
    // The angle first (a sample of the edges tells it on most meshes): the pass over the faces then
    // finds the crease candidates at it along with the volumes.
    const std::optional<float> angle = sampled_crease_angle(mesh, vf, crease_setting);
    const FaceSurvey survey = survey_faces(mesh, vf, angle.value_or(0.0f), p.box.center());
    p.turned_inside_out = is_inside_out(survey.volumes);
    // Turned round, every normal turns with the others: the bends, and so the candidates, stay.
    if (p.turned_inside_out) flip_faces(mesh, &vf);
    p.outside_out = p.turned_inside_out || is_outside_out(survey.volumes);
    if (angle) p.creases = {*angle, creases_around(mesh, vf, *angle, survey.crease_candidates)};
    else p.creases = resolve_creases(mesh, vf, crease_setting);
    return p;
}

std::string mesh_display_name(const std::string& path) { return path.empty() ? "built-in model" : path; }

}  // namespace kappa::app
