// `kappa render [MESH] -o OUT.png [options]`: headless line drawing to PNG
// (conventions.md, "Command line contract"). Curvature is estimated once,
// uploaded once, then each view (one, or N with --turntable) is drawn by the
// GLSL renderer in render/ into an offscreen framebuffer and written as an
// 8-bit RGBA PNG.
#include "cli_options.h"
#include "commands.h"
#include "heap_tuning.h"
#include "mesh_drawing.h"
#include "mesh_source.h"
#include "progress_bar.h"
#include "render_options.h"

#include "geometry/io/mesh_io.h"
#include "geometry/io/output_file.h"
#include "render/gl/egl_context.h"
#include "render/image/image_writer.h"
#include "render/vector/vector_drawing.h"

#include <glm/trigonometric.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace kappa::app {

namespace {

using Clock = std::chrono::steady_clock;

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
    keep_large_blocks();  // views reuse the last view's memory (app/heap_tuning.h)
    std::string mesh_path, out_path;
    int turntable = 0;
    bool quiet = false;
    RenderOptions options;
    const render::RenderSettings& s = options.settings;

    cli::Parser p("render", "[MESH] -o OUT.png [options]",
                  "Draw a mesh headless (EGL, no display needed) with occluding and suggestive contours, "
                  "shading, curvature colour maps and hatching, and write an 8-bit RGBA PNG.");
    p.positional("MESH", mesh_path, "mesh file (.ply .obj .off .stl .gltf .glb); default: the built-in model", false)
        .text("-o,--output", out_path, "output image: .png, or .jpg/.jpeg (opaque background only)", "OUT.png");
    add_render_options(p, options);
    p.integer("--turntable", turntable, "write N views around the model: OUT-000.png ... (default: one view)",
                 1, 100000)
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
    finish_render_options(p, options);
    options.camera.file_up = file_up_axis(mesh_path);  // glTF: +y
    const glm::ivec2 size = options.size;

    try {
        const auto t_load = Clock::now();
        Mesh input = load_mesh_or_default(mesh_path);
        if (input.face_count() == 0)
            return cli::fail(mesh_display_name(mesh_path) + ": the mesh has no faces: nothing to draw");
        ProgressBar bar(!quiet && input.face_count() >= 200000);
        MeshDrawing drawing(std::move(input), s, options.smoothing, [&](float x, const char* stage) {
            bar.update(x, stage);
        });
        bar.finish();
        const Mesh& mesh = drawing.mesh();
        const double load_s = seconds_since(t_load) - drawing.times().total() - drawing.scale_seconds();

        glm::vec3 orbit_center;
        glm::vec3 up_axis(0, 1, 0);
        const render::Camera camera =
            make_camera(options.camera, drawing, size, &orbit_center, &up_axis);

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
            const StageTimes& times = drawing.times();
            std::printf("%s: %zu vertices, %zu faces\n", mesh_display_name(mesh_path).c_str(), mesh.vertex_count(),
                        mesh.face_count());
            std::printf("  load %.3f s, curvature %.3f s (normals %.3f, curvature %.3f, dcurv %.3f, smoothing %.3f), "
                        "%s %.3f s\n",
                        load_s, times.total(), times.normals, times.curvature, times.dcurv, times.smoothing,
                        s.detail > 0 ? "scale space" : "feature size", drawing.scale_seconds());
            if (drawing.crease_count() > 0)
                std::printf("  %zu sharp edges (faces turning by more than %g degrees)\n", drawing.crease_count(),
                            drawing.crease_angle());
            if (drawing.turned_inside_out())
                std::printf("  the faces point inwards: drawn turned the right way round\n");
            if (s.detail > 0 && drawing.noise_floor() > 0)
                std::printf("  scan noise: no detail finer than %.4g model units\n", drawing.noise_floor());
            std::printf("  %s (context + shaders %.3f s)\n", context->description().c_str(), context_s);
        }

        // The turntable turns around the model's up axis (the one the default
        // view or --view stands on: +y, or the shape's, geometry/view/default_view.h)
        // through the centre; with --xf or --up, around the camera's own up axis
        // through the target.
        const bool own_up = !options.camera.xf_path.empty() || options.camera.has_up;
        const glm::vec3 axis = own_up ? glm::vec3(glm::inverse(camera.view) * glm::vec4(0, 1, 0, 0)) : up_axis;
        const int views = std::max(turntable, 1);
        for (int i = 0; i < views; ++i) {
            const render::Camera view =
                turntable ? camera.orbited(orbit_center, axis, float(2 * M_PI * i / views)) : camera;
            // Upload: once, or per view when the fields follow the view (--detail).
            const auto t_upload = Clock::now();
            const float view_fs = drawing.prepare_view(renderer, view, size);
            const double upload_s = seconds_since(t_upload);
            bar.finish();  // after curvature a view needed
            if (!quiet && (i == 0 || s.detail > 0)) {
                if (s.detail > 0) std::printf("  fields at %g px detail", s.detail);
                else std::printf("  fields");
                std::printf(", feature size %.6g: %.3f s (upload included)\n", drawing.units().length_to_model(view_fs),
                            upload_s);
                if (s.colormap != render::ColorMap::None)
                    std::printf("  colour map %s over %s%.6g]\n", render::to_string(s.colormap).c_str(),
                                s.colormap == render::ColorMap::DCurv ? "[0, " : "[-",
                                renderer.mesh()->map_range(s.colormap));
            }
            const std::string path = turntable ? numbered_path(out_path, i) : out_path;
            const auto t_render = Clock::now();
            if (vector_format) {
                drawing.write(renderer, view, s, size, path);
                if (!quiet)
                    std::printf("  wrote %s (%dx%d): render, strokes and write %.3f s\n", path.c_str(), size.x,
                                size.y, seconds_since(t_render));
                continue;
            }
            const render::Image image = drawing.image(renderer, view, s, size);
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
