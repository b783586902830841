// `kappa render [MESH] -o OUT.png [options]`: headless line drawing to PNG
// (conventions.md, "Command line contract"). Curvature is estimated once,
// uploaded once, then each view (one, or N with --turntable) is drawn by the
// GLSL renderer in render/ into an offscreen framebuffer and written as an
// 8-bit RGBA PNG.
#include "appearance_settings.h"
#include "cli_options.h"
#include "commands.h"
#include "mesh_source.h"
#include "progress_bar.h"

#include "geometry/creases.h"
#include "geometry/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/io/output_file.h"
#include "geometry/surface_analysis.h"
#include "geometry/view/default_view.h"
#include "render/camera.h"
#include "render/detail_fields.h"
#include "render/egl_context.h"
#include "render/image_writer.h"
#include "render/render_settings.h"
#include "render/renderer.h"
#include "render/vector_view.h"

#include <glm/trigonometric.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace kappa::app {

namespace {

using Clock = std::chrono::steady_clock;

// Largest image side: what OpenGL implementations commonly allow for a
// framebuffer (llvmpipe and current GPUs: 16384).
constexpr int kMaxImageSide = 16384;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// OUT.png -> OUT-007.png for turntable view 7.
std::string numbered_path(const std::string& path, int index) {
    const auto dot = path.find_last_of('.');
    const bool has_ext = dot != std::string::npos && path.find('/', dot) == std::string::npos;
    char number[16];
    std::snprintf(number, sizeof number, "-%03d", index);
    return has_ext ? path.substr(0, dot) + number + path.substr(dot) : path + number + ".png";
}

}  // namespace

int run_render(int argc, char** argv) {
    std::string mesh_path, out_path, xf_path;
    std::optional<ViewAngles> view_angles;
    glm::ivec2 size{1024, 768};
    glm::vec3 eye{0}, target{0}, up{0, 1, 0};
    float fov = 30.0f;
    int turntable = 0;
    bool quiet = false;
    SmoothingOptions smoothing;
    render::RenderSettings s;

    cli::Parser p("render", "[MESH] -o OUT.png [options]",
                  "Draw a mesh headless (EGL, no display needed) with occluding and suggestive contours, "
                  "shading, curvature colour maps and hatching, and write an 8-bit RGBA PNG.");
    p.positional("MESH", mesh_path, "mesh file (.ply .obj .off .stl .gltf .glb); default: the built-in model", false)
        .text("-o,--output", out_path, "output image: .png, or .jpg/.jpeg (opaque background only)", "OUT.png")
        .size("--size", size, "image size in pixels (default 1024x768)")
        .option("--view", "AZ,EL",
                "view from azimuth AZ (degrees around the y axis, 0 = from +z, 90 = from +x) and elevation EL "
                "(degrees above the xz plane), framing the model (default: a three-quarter view chosen per "
                "mesh, README 'Default view')",
                [&](const std::string& v) {
                    const auto parts = cli::split(v, ',');
                    if (parts.size() != 2) return false;
                    const auto az = cli::parse_number(parts[0]), el = cli::parse_number(parts[1]);
                    if (!az || !el || !std::isfinite(*az) || !(std::fabs(*el) <= 90)) return false;
                    view_angles = ViewAngles{float(*az), float(*el)};
                    return true;
                },
                "two numbers AZ,EL in degrees, EL in [-90, 90]")
        .vec3("--eye", eye, "camera position; without --target, only its direction counts and the model stays "
              "framed (default: the default view)")
        .vec3("--target", target, "point the camera looks at (default: the bounding sphere's centre)")
        .vec3("--up", up, "camera up direction (default 0,1,0)")
        .number("--fov", fov, "vertical field of view in degrees (default 30; with --xf the one rtsc uses for "
                "that image size, so views saved there match)", 1, 170, "DEG")
        .text("--xf", xf_path, "trimesh2/rtsc viewpoint file (4x4 model-view matrix)", "FILE");
    // Appearance: one table for render, view and the viewer's scripts (appearance_settings.h).
    for (const AppearanceSetting& a : appearance_settings()) {
        if (a.flag) {
            p.flag("--" + a.name, s.*a.flag, a.help);
            continue;
        }
        p.option("--" + a.name, a.metavar, a.help, [&s, &a](const std::string& v) { return a.set(s, v); },
                 a.expects);
    }
    p.integer("--turntable", turntable, "write N views around the model: OUT-000.png ... (default: one view)",
                 1, 100000)
        .smoothing(smoothing)
        .flag("-q,--quiet", quiet, "print nothing but errors")
        .threads()
        .epilog("With --shading none --colormap none the surface is white and only lines are dark.\n"
                "Lines follow the surface at the --detail scale; explicit --smooth-* widths and an --estimator\n"
                "other than rusinkiewicz override it (the raw per-vertex fields are drawn).\n"
                "--sc-threshold is divided by the square of the mesh's feature size fs (printed by 'kappa info'),\n"
                "so the same value means the same on every mesh.\n"
                "Examples:\n"
                "  kappa render bunny.ply -o bunny.png --detail 24   (calmer lines)\n"
                "  kappa render -o blob.png --shading none --eye 0,-2.6,1.85 --line-width 2.5\n"
                "  kappa render bunny.ply -o turn.png --turntable 12 --size 512x512");
    if (auto status = p.parse(argc, argv)) return *status;
    if (out_path.empty()) {
        std::fprintf(stderr, "kappa render: missing -o OUT.png (see 'kappa render --help')\n");
        return 2;
    }
    // Everything that can be checked before the mesh is read and curvature computed.
    const auto vector_format = render::vector_format_for(out_path);
    if (!render::image_format_for(out_path) && !vector_format) {
        std::fprintf(stderr, "kappa render: cannot tell the image format of '%s': use .png, .jpg, .jpeg, .svg or .pdf\n",
                     out_path.c_str());
        return 2;
    }
    if (render::image_format_for(out_path) == render::ImageFormat::Jpeg && s.background.a < 1.0f) {
        std::fprintf(stderr, "kappa render: %s: JPEG has no transparency (use .png, or an opaque --background)\n",
                     out_path.c_str());
        return 2;
    }
    if (auto problem = io::output_problem(out_path)) {
        std::fprintf(stderr, "kappa render: cannot write %s: %s\n", out_path.c_str(), problem->c_str());
        return 1;
    }
    if (size.x > kMaxImageSide || size.y > kMaxImageSide) {
        std::fprintf(stderr, "kappa render: --size %dx%d is too large (at most %dx%d)\n", size.x, size.y,
                     kMaxImageSide, kMaxImageSide);
        return 2;
    }
    const bool look_at = p.seen("--eye") || p.seen("--target") || p.seen("--up");
    if (!xf_path.empty() && (look_at || view_angles)) {
        std::fprintf(stderr, "kappa render: --xf cannot be combined with --view/--eye/--target/--up\n");
        return 2;
    }
    if (view_angles && (p.seen("--eye") || p.seen("--target"))) {
        std::fprintf(stderr, "kappa render: --view cannot be combined with --eye/--target\n");
        return 2;
    }

    try {
        const auto t_load = Clock::now();
        Mesh input = load_mesh_or_default(mesh_path);
        if (input.face_count() == 0)
            return cli::fail(mesh_display_name(mesh_path) + ": the mesh has no faces: nothing to draw");
        // Sharp edges split the mesh: each side gets its own normals and curvature.
        const float crease_angle = render::resolved_crease_angle(s.crease_angle, input);
        const std::vector<glm::uvec2> creases = find_creases(input, crease_angle);
        const SplitMesh drawn = split_at_creases(std::move(input), creases);
        const Mesh& mesh = drawn.mesh;
        const double load_s = seconds_since(t_load);

        // Explicit smoothing widths override the detail setting (README, "kappa render").
        // So does an estimator other than the default: the scale space is built on the paper's fits,
        // so the chosen estimator's own per-vertex fields are drawn.
        if (p.seen("--smooth-normals") || p.seen("--smooth-curvature") || p.seen("--smooth-dcurv") ||
            smoothing.estimator != Estimator::rusinkiewicz)
            s.detail = 0;
        // With detail, the per-vertex curvature is needed only where a view
        // blends in the raw estimate (zoomed in on a coarse mesh): computed then.
        ProgressBar bar(!quiet && mesh.face_count() >= 200000);
        StageTimes times;
        const auto compute_fields = [&] {
            SurfaceFields f = compute_surface_fields(mesh, smoothing, &times,
                                                     [&](float x, const char* stage) { bar.update(x, stage); });
            bar.finish();
            return f;
        };
        SurfaceFields fields =
            s.detail > 0 && !smoothing.automatic ? compute_surface_normals(mesh, &times) : compute_fields();
        const auto t_fs = Clock::now();
        render::DetailSource detail_source;
        if (s.detail > 0) detail_source = render::make_detail_source(mesh, fields);
        const float fs = s.detail > 0 ? 0.0f : feature_size(mesh, fields);  // with detail: per view
        const double fs_s = seconds_since(t_fs);

        // Camera: .xf file, eye/target/up, or framing the bounding sphere.
        const render::BoundingSphere bounds = render::bounding_sphere(mesh);
        const std::vector<CreaseEdge> crease_edges =
            vector_format ? kappa::crease_edges(mesh, drawn.creases, drawn.crease_faces) : std::vector<CreaseEdge>{};
        const float aspect = float(size.x) / float(size.y);
        render::Camera camera;
        glm::vec3 orbit_center = bounds.center;
        if (!xf_path.empty()) {
            camera.view = render::read_xf(xf_path);
            camera.fov_y_deg = p.seen("--fov") ? fov : render::rtsc_fov_y_deg(size.x, size.y);
        } else {
            // The default view, or --view's angles, or --eye's direction: framed.
            camera = view_angles ? render::Camera::framing(bounds, fov, aspect, view_direction(*view_angles))
                     : p.seen("--eye") ? render::Camera::framing(bounds, fov, aspect, eye - bounds.center)
                                       : render::Camera::default_view(mesh, bounds, fov, aspect);
            if (p.seen("--target") || p.seen("--up")) {  // the user's own camera
                if (!p.seen("--eye")) eye = camera.eye();
                if (!p.seen("--target")) {
                    target = bounds.center;
                    eye = camera.eye();  // framed along --eye's direction
                }
                if (glm::length(glm::cross(target - eye, up)) < 1e-12f * glm::length(target - eye) ||
                    glm::length(target - eye) == 0)
                    throw cli::UsageError("kappa render: --eye and --target must differ, and --up must not be "
                                          "parallel to the viewing direction");
                camera = render::Camera::look_at(eye, target, up, fov);
                orbit_center = target;
            }
        }

        const auto t_context = Clock::now();
        std::unique_ptr<render::HeadlessContext> context;
        try {
            context = render::HeadlessContext::create();
        } catch (const render::ContextError& e) {
            return cli::fail(e.what());
        }
        render::Renderer renderer;
        const double context_s = seconds_since(t_context);
        if (!quiet) {
            std::printf("%s: %zu vertices, %zu faces\n", mesh_display_name(mesh_path).c_str(), mesh.vertex_count(),
                        mesh.face_count());
            std::printf("  load %.3f s, curvature %.3f s (normals %.3f, curvature %.3f, dcurv %.3f, smoothing %.3f), "
                        "%s %.3f s\n",
                        load_s, times.total(), times.normals, times.curvature, times.dcurv, times.smoothing,
                        s.detail > 0 ? "scale space" : "feature size", fs_s);
            if (!drawn.creases.empty())
                std::printf("  %zu sharp edges (faces turning by more than %g degrees)\n", drawn.creases.size(),
                            crease_angle);
            if (s.detail > 0 && detail_source.noise_floor > 0)
                std::printf("  scan noise: no detail finer than %.4g model units\n", detail_source.noise_floor);
            std::printf("  %s (context + shaders %.3f s)\n", context->description().c_str(), context_s);
        }

        // The turntable turns around the model's y axis (the up of the default
        // view and of --view) through the centre; with --xf or --up, around
        // the camera's own up axis through the target.
        const bool own_up = !xf_path.empty() || p.seen("--up");
        const glm::vec3 axis =
            own_up ? glm::vec3(glm::inverse(camera.view) * glm::vec4(0, 1, 0, 0)) : glm::vec3(0, 1, 0);
        const int views = std::max(turntable, 1);
        for (int i = 0; i < views; ++i) {
            const render::Camera view =
                turntable ? camera.orbited(orbit_center, axis, float(2 * M_PI * i / views)) : camera;
            // Upload: once, or per view when the fields follow the view (--detail).
            const auto t_upload = Clock::now();
            float view_fs = fs;
            render::DetailFields d;  // with detail: this view's fields
            const SurfaceFields* view_fields = &fields;
            if (s.detail > 0) {
                const render::ViewScales scales = render::view_scales(mesh, detail_source, view, size.y, s.detail);
                if (!fields.has_curvature() && render::needs_raw_curvature(detail_source, scales))
                    fields = compute_fields();
                d = render::detail_fields(mesh, detail_source, fields, scales);
                view_fs = d.feature_size;
                view_fields = &d.fields;
                if (i == 0) {
                    renderer.set_mesh(mesh, d.fields, view_fs, d.fine_normals);
                    renderer.set_creases(render::crease_end_points(drawn));
                }
                else renderer.update_fields(mesh, d.fields, view_fs, d.fine_normals);
            } else if (i == 0) {
                view_fields = &fields;
                renderer.set_mesh(mesh, fields, fs);
                renderer.set_creases(render::crease_end_points(drawn));
            }
            const double upload_s = seconds_since(t_upload);
            if (!quiet && (i == 0 || s.detail > 0)) {
                if (s.detail > 0) std::printf("  fields at %g px detail", s.detail);
                else std::printf("  fields");
                std::printf(", feature size %.6g: %.3f s (upload included)\n", view_fs, upload_s);
                if (s.colormap != render::ColorMap::None)
                    std::printf("  colour map %s over %s%.6g]\n", render::to_string(s.colormap).c_str(),
                                s.colormap == render::ColorMap::DCurv ? "[0, " : "[-",
                                renderer.mesh()->map_range(s.colormap));
            }
            const std::string path = turntable ? numbered_path(out_path, i) : out_path;
            const auto t_render = Clock::now();
            if (vector_format) {
                const render::StrokeSource source{&mesh, view_fields, &d.fine_normals, &crease_edges, view_fs};
                render::write_vector_view(renderer, view, s, size.x, size.y, source, *vector_format, path);
                if (!quiet)
                    std::printf("  wrote %s (%dx%d): render, strokes and write %.3f s\n", path.c_str(), size.x,
                                size.y, seconds_since(t_render));
                continue;
            }
            const render::Image image = render::render_to_image(renderer, view, s, size.x, size.y);
            const double render_s = seconds_since(t_render);
            const auto t_write = Clock::now();
            render::write_image(path, image);
            if (!quiet)
                std::printf("  wrote %s (%dx%d): render %.3f s, write %.3f s\n", path.c_str(), size.x, size.y,
                            render_s, seconds_since(t_write));
        }
        return 0;
    } catch (const MeshLoadError& e) {
        return cli::fail(e.what());
    }
}

}  // namespace kappa::app
