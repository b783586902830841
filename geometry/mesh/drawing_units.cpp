#include "drawing_units.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

glm::vec3 DrawingUnits::to_drawing(glm::vec3 p) const { return glm::vec3((glm::dvec3(p) - centre) / scale); }
glm::vec3 DrawingUnits::to_model(glm::vec3 p) const { return glm::vec3(centre + glm::dvec3(p) * scale); }

glm::mat4 DrawingUnits::view_to_drawing(const glm::mat4& model_view) const {
    if (identity()) return model_view;
    // Drawing point q is model point centre + scale q; camera units shrink by scale too.
    const glm::dmat4 from_drawing = glm::scale(glm::translate(glm::dmat4(1.0), centre), glm::dvec3(scale));
    const glm::dmat4 shrink = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 / scale));
    return glm::mat4(shrink * glm::dmat4(model_view) * from_drawing);
}

DrawingUnits drawing_units(const Mesh& mesh) { return drawing_units(position_bounds(mesh.positions)); }

DrawingUnits drawing_units(const PositionBounds& box) {
    DrawingUnits units;
    if (box.empty()) return units;
    const glm::dvec3 lo(box.lo), hi(box.hi);  // the float bounds, exactly
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = 0.5 * glm::length(hi - lo);
    if (!(radius > 0) || !std::isfinite(radius) || (radius >= 1e-12 && radius <= 1e12)) return units;
    units.centre = centre;
    units.scale = radius;
    return units;
}

void to_drawing_units(Mesh& mesh, const DrawingUnits& units) {
    if (units.identity()) return;
    for (glm::vec3& p : mesh.positions) p = units.to_drawing(p);
}

}  // namespace kappa
