// A perspective camera: a model-view matrix (model -> camera coordinates,
// camera at the origin looking down -z, y up; the trimesh2/rtsc convention)
// and a vertical field of view. Built from eye/target/up, by framing a
// bounding sphere, or from a trimesh2/rtsc .xf file.
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/mesh/position_bounds.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace kappa::render {

struct BoundingSphere {
    glm::vec3 center{0};
    float radius = 1;
};

// Centre of the bounding box, radius to the farthest vertex.
BoundingSphere bounding_sphere(const Mesh& mesh);
// The same with the mesh's position_bounds (geometry/mesh/position_bounds.h) given.
BoundingSphere bounding_sphere(const Mesh& mesh, const PositionBounds& box);

struct Camera {
    glm::mat4 view{1};     // model -> camera coordinates
    float fov_y_deg = 30;  // vertical field of view

    static Camera look_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float fov_y_deg);
    // Looks at the sphere's centre from `direction` (from the centre towards
    // the eye; default +z), `up` up (default +y; looking along it, the
    // frame's front points down the image: geometry/view/default_view.h's
    // view_frame), as close as the whole sphere fits in the image (aspect =
    // width / height).
    static Camera framing(const BoundingSphere& sphere, float fov_y_deg, float aspect,
                          glm::vec3 direction = glm::vec3(0, 0, 1), glm::vec3 up = glm::vec3(0, 1, 0));
    // kappa's default view of a mesh (geometry/view/default_view.h: its up
    // axis, from the shape unless `up` is given, and the view about it), framed.
    static Camera default_view(const Mesh& mesh, const BoundingSphere& sphere, float fov_y_deg, float aspect,
                               std::optional<glm::vec3> up = std::nullopt);

    glm::vec3 eye() const;  // in model coordinates
    // Perspective projection with near/far planes tight around `sphere`.
    glm::mat4 projection(const BoundingSphere& sphere, float aspect) const;
    // The camera turned by `radians` around the axis through `center` along
    // `axis` (model coordinates): turntable views.
    Camera orbited(glm::vec3 center, glm::vec3 axis, float radians) const;
};

// rtsc/trimesh2 default field of view for an image of this size: their
// GLCamera uses tan(fov_y / 2) = 0.35 * height / diagonal.
float rtsc_fov_y_deg(int width, int height);

// A trimesh2/rtsc viewpoint file: the 4x4 model-view matrix, written as
// trimesh2's XForm does (four lines, one matrix row each: the in-memory
// column-major array m[16] printed as m[i + 4j] row by row; the fourth row
// may be missing). Throws std::runtime_error "PATH: problem".
glm::mat4 read_xf(const std::string& path);
void write_xf(const std::string& path, const glm::mat4& view);

}  // namespace kappa::render
