#include "render_options.h"

#include "appearance_settings.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace kappa::app {

namespace {

// Largest image side: what OpenGL implementations commonly allow for a
// framebuffer (llvmpipe and current GPUs: 16384).
constexpr int kMaxImageSide = 16384;

}  // namespace

void add_render_options(cli::Parser& p, RenderOptions& o) {
    CameraOptions& c = o.camera;
    p.size("--size", o.size, "image size in pixels (default 1024x768)")
        .option("--view", "AZ,EL",
                "view from azimuth AZ (degrees around the y axis, 0 = from +z, 90 = from +x) and elevation EL "
                "(degrees above the xz plane), framing the model; with --up, about that axis instead (for up "
                "0,0,1: 0 = from -y, 90 = from +x) (default: a three-quarter view chosen per mesh, "
                "docs/rendering.md, 'The default view')",
                [&c](const std::string& v) {
                    c.view = parse_view_angles(v);
                    return c.view.has_value();
                },
                "two numbers AZ,EL in degrees, EL in [-90, 90]")
        .vec3("--eye", c.eye, "camera position; without --target, only its direction counts and the model stays "
              "framed (default: the default view)")
        .vec3("--target", c.target, "point the camera looks at (default: the bounding sphere's centre)")
        .vec3("--up", c.up, "the model's up axis: the default view and --view are taken about it, and it points "
              "up in the image; with --eye, the camera's up direction (default: the file's convention or the "
              "model's shape for the default view, 0,1,0 otherwise; kappa info prints the default view's)")
        .number("--fov", c.fov, "vertical field of view in degrees (default 30; with --xf the one rtsc uses for "
                "that image size, so views saved there match)", 1, 170, "DEG")
        .text("--xf", c.xf_path, "trimesh2/rtsc viewpoint file (4x4 model-view matrix)", "FILE");
    // Appearance: one table for render, view and the viewer's scripts (appearance_settings.h).
    render::RenderSettings& s = o.settings;
    for (const AppearanceSetting& a : appearance_settings()) {
        if (a.flag) {
            p.flag("--" + a.name, s.*a.flag, a.help);
            continue;
        }
        p.option("--" + a.name, a.metavar, a.help, [&s, &a](const std::string& v) { return a.set(s, v); },
                 a.expects);
    }
    p.smoothing(o.smoothing);
}

std::optional<ViewAngles> parse_view_angles(const std::string& text) {
    const auto parts = cli::split(text, ',');
    if (parts.size() != 2) return std::nullopt;
    const auto az = cli::parse_number(parts[0]), el = cli::parse_number(parts[1]);
    if (!az || !el || !std::isfinite(*az) || !(std::fabs(*el) <= 90)) return std::nullopt;
    return ViewAngles{float(*az), float(*el)};
}

void finish_render_options(const cli::Parser& p, RenderOptions& o) {
    CameraOptions& c = o.camera;
    c.has_eye = p.seen("--eye");
    c.has_target = p.seen("--target");
    c.has_up = p.seen("--up");
    c.has_fov = p.seen("--fov");
    if (o.size.x > kMaxImageSide || o.size.y > kMaxImageSide)
        throw p.error("--size " + std::to_string(o.size.x) + "x" + std::to_string(o.size.y) +
                      " is too large (at most " + std::to_string(kMaxImageSide) + "x" + std::to_string(kMaxImageSide) +
                      ")");
    if (c.has_up && !(glm::length(c.up) > 0 && std::isfinite(glm::length(c.up))))
        throw p.error("--up must be a non-zero direction");
    const bool look_at = c.has_eye || c.has_target || c.has_up;
    if (!c.xf_path.empty() && (look_at || c.view))
        throw p.error("--xf cannot be combined with --view/--eye/--target/--up");
    if (c.view && (c.has_eye || c.has_target)) throw p.error("--view cannot be combined with --eye/--target");
    // Explicit smoothing widths override the detail setting (docs/detail-and-noise.md).
    // So does an estimator other than the default: the scale space is built on the paper's fits,
    // so the chosen estimator's own per-vertex fields are drawn.
    if (p.seen("--smooth-normals") || p.seen("--smooth-curvature") || p.seen("--smooth-dcurv") ||
        o.smoothing.estimator != Estimator::rusinkiewicz)
        o.settings.detail = 0;
}

bool same_smoothing(const SmoothingOptions& a, const SmoothingOptions& b) {
    return a.normals == b.normals && a.curvature == b.curvature && a.dcurv == b.dcurv &&
           a.automatic == b.automatic && a.estimator == b.estimator;
}

render::Camera make_camera(const CameraOptions& options, const Mesh& mesh, const render::BoundingSphere& bounds,
                           glm::ivec2 size, glm::vec3* orbit_center, const DrawingUnits& units,
                           glm::vec3* up_axis, bool denoised, const VertexFaces* vf) {
    CameraOptions c = options;
    c.eye = units.to_drawing(c.eye), c.target = units.to_drawing(c.target);
    const float aspect = float(size.x) / float(size.y);
    if (orbit_center) *orbit_center = bounds.center;
    if (up_axis) *up_axis = c.has_up ? view_frame(c.up).up : glm::vec3(0, 1, 0);
    render::Camera camera;
    if (!c.xf_path.empty()) {
        camera.view = units.view_to_drawing(render::read_xf(c.xf_path));
        camera.fov_y_deg = c.has_fov ? c.fov : render::rtsc_fov_y_deg(size.x, size.y);
        return camera;
    }
    // --view's angles (about --up when given, else about +y), or the
    // default view (about --up when given, else about the up axis the file or
    // the shape gives), framed with that axis up.
    if (!c.has_eye) {
        const std::optional<glm::vec3> up = c.has_up ? std::optional<glm::vec3>(c.up) : c.file_up;
        if (!c.view) {
            const DefaultView v = default_view_as_read(mesh, up, denoised, vf);
            if (up_axis) *up_axis = v.up;
            camera = render::Camera::framing(bounds, c.fov, aspect, v.eye, v.up);  // = Camera::default_view
        } else {
            camera = c.has_up ? render::Camera::framing(bounds, c.fov, aspect, view_direction(*c.view, c.up), c.up)
                              : render::Camera::framing(bounds, c.fov, aspect, view_direction(*c.view));
        }
        // The default view with --up goes on as before the up axis counted
        // (a look_at from the framed eye: the same camera, to the last bit).
        if (!c.has_target && (c.view || !c.has_up)) return camera;
    } else {
        // --eye's direction, framed.
        camera = render::Camera::framing(bounds, c.fov, aspect, c.eye - bounds.center);
        if (!c.has_target && !c.has_up) return camera;
    }
    // The user's own camera.
    glm::vec3 eye = c.has_eye ? c.eye : camera.eye(), target = c.target;
    if (!c.has_target) {
        target = bounds.center;
        eye = camera.eye();  // framed along --eye's direction
    }
    if (glm::length(glm::cross(target - eye, c.up)) < 1e-12f * glm::length(target - eye) ||
        glm::length(target - eye) == 0)
        throw cli::UsageError("kappa render: --eye and --target must differ, and --up must not be "
                              "parallel to the viewing direction");
    if (orbit_center) *orbit_center = target;
    return render::Camera::look_at(eye, target, c.up, c.fov);
}

}  // namespace kappa::app
