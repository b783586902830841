// The options of `kappa render` that say what to draw and from where: image
// size, camera, every appearance setting (appearance_settings.h) and the
// curvature options. Declared once here for `kappa render`, each line of
// `kappa batch` manifests and the Python module's render() (which spells its
// keyword arguments as these options).
#pragma once

#include "cli_options.h"

#include "geometry/mesh/drawing_units.h"
#include "geometry/surface_fields.h"
#include "geometry/view/default_view.h"
#include "render/camera/camera.h"
#include "render/render_settings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace kappa::app {

struct CameraOptions {
    std::string xf_path;              // --xf
    std::optional<ViewAngles> view;   // --view AZ,EL
    glm::vec3 eye{0}, target{0}, up{0, 1, 0};
    float fov = 30.0f;
    bool has_eye = false, has_target = false, has_up = false, has_fov = false;  // given explicitly
    // The up axis the mesh file's format fixes (file_up_axis of its path:
    // +y for glTF), used by the default view when --up is not given.
    std::optional<glm::vec3> file_up;

    // Whether the camera is the default view (no --xf, --eye or --view): make_camera reads the surface then.
    bool uses_default_view() const { return xf_path.empty() && !has_eye && !view; }
};

struct RenderOptions {
    glm::ivec2 size{1024, 768};
    CameraOptions camera;
    render::RenderSettings settings;
    SmoothingOptions smoothing;
};

// Declares --size, --view, --eye, --target, --up, --fov, --xf, the appearance
// settings and the curvature options (--estimator, --smooth*) on `p`.
void add_render_options(cli::Parser& p, RenderOptions& options);

// --view's "AZ,EL": degrees, the elevation in [-90, 90]; nullopt otherwise.
std::optional<ViewAngles> parse_view_angles(const std::string& text);

// After p.parse: records which camera options were given and checks them
// together (throws cli::UsageError "kappa CMD: problem"). Explicit smoothing
// widths and estimators other than the default turn --detail off
// (docs/detail-and-noise.md).
void finish_render_options(const cli::Parser& p, RenderOptions& options);

// Whether two curvature settings ask for the same fields.
bool same_smoothing(const SmoothingOptions& a, const SmoothingOptions& b);

// The camera the options describe for `mesh` (bounds: its bounding sphere)
// in an image of `size`: --xf, --view, --eye/--target/--up or the default
// view. orbit_center (optional): where a turntable turns around. up_axis
// (optional): the model's up axis the view stands on (--up, else the
// default view's, else +y; model coordinates): the axis a turntable of the
// default view or of --view turns about (app/cmd_render.cpp). Throws
// cli::UsageError for a degenerate eye/target/up and std::runtime_error
// for an unreadable --xf file. mesh: the surface as the default view reads it
// (MeshDrawing::view_surface: denoised when noisy; denoised says so, for
// default_view.h's choose_up). mesh, bounds and the result are in drawing
// units (geometry/mesh/drawing_units.h: MeshDrawing::units()); --eye, --target
// and --xf, in model units, are converted. vf: mesh's vertex-face rows, when
// the caller has them (the default view is then quicker on big meshes).
render::Camera make_camera(const CameraOptions& options, const Mesh& mesh, const render::BoundingSphere& bounds,
                           glm::ivec2 size, glm::vec3* orbit_center = nullptr, const DrawingUnits& units = {},
                           glm::vec3* up_axis = nullptr, bool denoised = false, const VertexFaces* vf = nullptr);

}  // namespace kappa::app
