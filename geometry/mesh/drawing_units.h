// Meshes far from unit size break float arithmetic when drawn: squared
// lengths and the projection's near x far overflow above a radius of about
// 1e19, squared curvatures below about 1e-19. A mesh whose bounding
// radius lies outside [1e-12, 1e12] is drawn from a copy moved to the origin
// and scaled to unit radius. Line drawings do not change under that
// similarity (thresholds are in units of the feature size, widths and
// detail in pixels), so the pictures are the same; what is given in model
// units (cameras, smoothing widths) is converted, and what is printed in
// model units converted back (but for the colour bar's labels, which give
// curvature per drawing unit). Meshes of ordinary size are drawn as they are.
#pragma once

#include "mesh.h"
#include "position_bounds.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace kappa {

struct DrawingUnits {
    glm::dvec3 centre{0.0};
    double scale = 1.0;  // model units per drawing unit

    bool identity() const { return scale == 1.0 && centre == glm::dvec3(0.0); }
    glm::vec3 to_drawing(glm::vec3 model_point) const;
    glm::vec3 to_model(glm::vec3 drawing_point) const;
    float length_to_drawing(float model_length) const { return float(double(model_length) / scale); }
    float length_to_model(float drawing_length) const { return float(double(drawing_length) * scale); }
    // A model-view matrix of the model (model units in, camera units out) as
    // the model-view matrix of the drawing copy, with camera units scaled alike.
    glm::mat4 view_to_drawing(const glm::mat4& model_view) const;
};

// Identity for radii in [1e-12, 1e12] (and for meshes without vertices).
DrawingUnits drawing_units(const Mesh& mesh);
// The same from the mesh's position_bounds.
DrawingUnits drawing_units(const PositionBounds& box);
// Moves the mesh's vertices into drawing units.
void to_drawing_units(Mesh& mesh, const DrawingUnits& units);

}  // namespace kappa
