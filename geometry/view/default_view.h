// kappa's default view of a mesh: a three-quarter view from above, turned to
// the side that shows the most of the shape.
//
// Candidates: azimuths every 15 degrees around the y axis (0 = looking from
// +z, 90 = from +x), leaving out the four axis-aligned ones (a plain front
// or side view flattens CAD parts into their outline), at elevations 20 and
// 35 degrees above the xz plane; y up (or the up axis below: then all of
// this is about it, in the coordinates of its view_frame).
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
// part with a level top have none. A model without such a front that is
// mirror-symmetric about a vertical plane, one end of the plane's
// horizontal direction pointed and the other round (a nose and the back of
// a skull: heads, busts), has its face at the pointed end (front_of_face in
// default_view.cpp) and is seen from within 50 degrees of it, whatever the
// score says (hair is more curved than a face). Large meshes are sampled:
// every ceil(F / 200000)-th face, so the choice is deterministic.
//
// Up: +y (the convention of most mesh formats and of glTF) unless the shape
// says clearly otherwise; only +z, the other convention in use (STL, CAD,
// many scans), can take its place. The evidence is a flat base: faces within
// 5 degrees of perpendicular to an axis, in the slab of 2% of the model's
// extent at one end of it (either side facing out, so inconsistently
// oriented meshes count too), as a share of the whole surface. +z replaces
// y when the flat area at the low end of z is at least 2% of the surface,
// no less than at its high end, at least four times that at either end of
// y and twice that at either end of x, and the model is not thin along z
// (extent at least half the largest): a bust or a part for 3D printing
// standing on its base. A standing figure has little base (its soles) but a
// clear long axis: when z is at least twice as long as x and y, a base of
// 0.5% of the surface is enough and need only match y's ends. A scan read
// denoised (default_view below) has lost flat faces smaller than its
// denoising scale, a figure's soles among them: there a long z axis whose
// low end is the blunter, its 2% slab holding at least 1.1 times the surface
// of the high end's, is enough (measured on the test figure with noise of
// 0.1 to 0.5 edges, seeds 1-4: 1.23 to 1.63, 2.1 clean; standing on its
// head, 1 / 1.23 or less). A cube, a plate, a model with a flat back or top,
// anything upside down in its file and everything without a clear flat end
// keep +y. The views above are then taken in the frame of that up axis
// (view_frame), front rule included.
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace kappa {

struct ViewAngles {
    float azimuth = 0;    // degrees around +y, from +z towards +x
    float elevation = 0;  // degrees above the xz plane
};

// Unit vector from the model towards the eye, y up.
glm::vec3 view_direction(ViewAngles angles);

// The frame that angles are taken in when `up` is up: the rotation by the
// smallest angle that takes +y to up, applied to x, y, z (so azimuth 0
// looks from `front`, 90 from `right`). For up = +z: right +x, front -y
// (the front view of z-up modelling tools); for up = -y: right +x, front -z.
// up need not be unit; a zero or non-finite up gives the y-up frame.
struct ViewFrame {
    glm::vec3 right{1, 0, 0}, up{0, 1, 0}, front{0, 0, 1};
};
ViewFrame view_frame(glm::vec3 up);

// Unit vector from the model towards the eye, the angles taken about `up`
// (view_frame). Equals view_direction(angles) for up = +y.
glm::vec3 view_direction(ViewAngles angles, glm::vec3 up);

// The model's up axis by its shape (see above): a unit axis direction, +y
// unless the evidence for another is clear. denoised: the mesh is a noisy
// scan read denoised (denoise.h's denoised_if_noisy), so small flat bases
// cannot show and a standing figure's blunter end counts instead.
glm::vec3 choose_up(const Mesh& mesh, bool denoised = false);

// The default view's angles (see above), about +y. A mesh with no face area
// gets azimuth 30, elevation 20.
// vf: the mesh's vertex-face rows (vertex_faces.h), when the caller has
// them: the vertex normals are then summed only where the sampled faces need
// them (the same sums; on big meshes most of the default view's time).
ViewAngles choose_default_view(const Mesh& mesh, const VertexFaces* vf = nullptr);
// The same about `up` (any non-zero direction; the view_frame of up).
ViewAngles choose_default_view(const Mesh& mesh, glm::vec3 up, const VertexFaces* vf = nullptr);

struct DefaultView {
    glm::vec3 eye{0, 0, 1};  // unit, from the model's centre towards the eye
    glm::vec3 up{0, 1, 0};   // unit, the model's up axis (the camera's up)
    ViewAngles angles;       // eye = view_direction(angles, up)
};
// The whole default view: up = `up` when given (--up, or the file's own
// convention), else choose_up(mesh); the angles about it. A noisy mesh
// (noise level of 8.5% of the edge or more, geometry/scale/denoise.h) is
// read denoised at its noise floor, so that a scan is seen as its clean
// shape is.
DefaultView default_view(const Mesh& mesh, std::optional<glm::vec3> up = std::nullopt);
// The same for a mesh read as given: the caller has denoised it already
// (denoised: true), or knows that it is not noisy (app/mesh_drawing.h's
// view_surface, which takes both from the detail pipeline's own noise
// estimate).
DefaultView default_view_as_read(const Mesh& surface, std::optional<glm::vec3> up = std::nullopt,
                                 bool denoised = false, const VertexFaces* vf = nullptr);

// The up axis a file's format fixes, by its extension: +y for glTF (.gltf,
// .glb: the reader gives the specification's +y up); none for the others.
std::optional<glm::vec3> file_up_axis(const std::string& path);

}  // namespace kappa
