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
// elevation 20 before 35. Occlusion is ignored.
// Never from behind: shape alone cannot tell a cow's face from its rump (both
// are rounded and about as curved), so a model that has a front by the test
// below is not shown from more than 120 degrees away from it; the best view
// within 50 degrees of its front is taken instead. The front: animals,
// figures and vehicles are longer than wide and carry their tallest parts at
// the front end (a head, horns, ears, a cab). When the horizontal second
// moments have a clear long axis (ratio >= 1.5) and the top fifth of the
// model by height lies towards one end of it (centroid >= 0.2 of the
// half-length off the whole's), that end is the front. A cube, a vase, a
// part with a level top have none. Large meshes are sampled:
// every ceil(F / 200000)-th face, so the choice is deterministic.
#pragma once

#include "geometry/mesh/mesh.h"

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
