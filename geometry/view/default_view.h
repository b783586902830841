// kappa's default view of a mesh: a three-quarter view from above, turned to
// the side that shows the most of the shape.
//
// Candidates: azimuths every 15 degrees around the y axis (0 = looking from
// +z, 90 = from +x), leaving out the four axis-aligned ones (a plain front
// or side view flattens CAD parts into their outline), at elevations 20 and
// 35 degrees above the xz plane; y stays up, as in the models' own frames.
// Score of a direction d (after the viewpoint entropy of Vazquez et al.
// 2001, "Viewpoint selection using viewpoint entropy", with the surface
// binned by orientation instead of by polygon, so tessellation does not
// count): the faces facing d weigh their projected area A (n . d); the
// entropy H of that weight over 64 bins of normal directions (a Fibonacci
// sphere) says how many differently turned surfaces are seen, and the
// projected area P, relative to the largest over the candidates, how much of
// the model. Score = H / ln 64 + 0.5 P / P_max. Ties (within 1e-6) go to
// the candidate first in the order: azimuth 30, -30, 45, -45, ... then
// elevation 20 before 35. Occlusion is ignored. Large meshes are sampled:
// every ceil(F / 200000)-th face, so the choice is deterministic.
#pragma once

#include "geometry/mesh.h"

#include <glm/vec3.hpp>

namespace kappa {

struct ViewAngles {
    float azimuth = 0;    // degrees around +y, from +z towards +x
    float elevation = 0;  // degrees above the xz plane
};

// Unit vector from the model towards the eye.
glm::vec3 view_direction(ViewAngles angles);

// The default view (see above). A mesh with no face area gets azimuth 30,
// elevation 20.
ViewAngles choose_default_view(const Mesh& mesh);

}  // namespace kappa
