// Frame time of the line-drawing renderer at 1024x768 (issue 3, "Speed"),
// frames as the viewer draws them (the compute line path never waits); gpu:
// the GL's own time for the frame's commands (a timer query), beside wall:
// median of 20 frames, for plain Lambertian shading and for contours +
// suggestive contours + hatching, on the default model and bunny-1M.ply;
// and with every line type of --lines on (issue 12: at most 1.5x the
// contours + suggestive frame), the ratio printed.
//   bench_render [--size WxH] [--frames N] [--each] [--detail PX] [--only NAME] [--no-msaa] [MESH ...]   (default: built-in
//   model and ../shared/meshes/bunny-1M.ply next to the repository; --each: also every line type
//   alone; --detail: the fields at that scale for the view, as kappa render draws by default,
//   instead of the raw 1-ring fields; --only: Lambert and the configurations whose name contains NAME,
//   e.g. to profile one; --no-msaa: only the frames without multisampling)
//   --line-pass: also the CPU line pass alone (render/lines/cpu_lines.h: extraction, chaining and merging,
//   no drawing and nothing else running), contours + suggestive and every line type, and the CPU
//   depth raster alone (render/surface/depth_raster.h), wall and CPU
#include "geometry/mesh/default_model.h"
#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/surface_analysis.h"
#include "render/fields/detail_fields.h"
#include "render/lines/cpu_lines.h"
#include "render/surface/depth_raster.h"
#include "render/gl/egl_context.h"
#include "render/camera/frame_params.h"
#include "render/gl/framebuffer.h"
#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

using namespace kappa;

namespace {

struct Config {
    const char* name;
    render::RenderSettings settings;
};

struct FrameTime {
    double wall_ms, cpu_ms;  // medians; CPU time of the whole process (llvmpipe's threads included)
    double gpu_ms = 0;       // median of the GL's own time for the frame's commands (GL_TIME_ELAPSED)
    double extract_ms = 0, draw_ms = 0;  // medians of the line passes' GPU times (LineRenderer::gpu_times)
};

// Process CPU time: less disturbed than wall time when other jobs share the machine.
double cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

FrameTime median_frame_ms(render::Renderer& renderer, const render::Camera& camera, const render::RenderSettings& s,
                          const render::Framebuffer& target, int frames) {
    const int w = target.spec().width, h = target.spec().height;
    // Warm-up: shader compilation, buffer allocation, and at least 0.3 s of frames, so that a GPU
    // whose clocks fell during a slow configuration (streamline hatching waits on the CPU) is back
    // at speed: measured after the slow one without this, frames took up to 4 times as long.
    const auto warm_start = std::chrono::steady_clock::now();
    do {
        renderer.render_offscreen(camera, s, w, h);  // as kappa render draws
        glFinish();
    } while (std::chrono::steady_clock::now() - warm_start < std::chrono::milliseconds(300));
    std::vector<double> wall, cpu, gpu, extract, draw;
    GLuint query = 0;
    glGenQueries(1, &query);
    for (int i = 0; i < frames; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = cpu_ms();
        glBeginQuery(GL_TIME_ELAPSED, query);
        renderer.render_offscreen(camera, s, w, h);  // as kappa render draws
        glEndQuery(GL_TIME_ELAPSED);
        glFinish();
        cpu.push_back(cpu_ms() - c0);
        wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        GLuint64 ns = 0;
        glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
        gpu.push_back(double(ns) * 1e-6);
        extract.push_back(renderer.line_gpu_times().extract_ms);
        draw.push_back(renderer.line_gpu_times().draw_ms);
    }
    glDeleteQueries(1, &query);
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    for (auto* v : {&gpu, &extract, &draw}) std::sort(v->begin(), v->end());
    return {wall[wall.size() / 2], cpu[cpu.size() / 2], gpu[gpu.size() / 2], extract[extract.size() / 2],
            draw[draw.size() / 2]};
}

// The CPU line pass alone: CpuLinePass::prepare, with the GL idle.
FrameTime median_line_pass_ms(const render::MeshBuffers& mesh, const render::Camera& camera,
                              const render::RenderSettings& s, int width, int height, int frames) {
    const render::CpuLinePass pass;
    const auto frame = render::FrameParams::make(camera, mesh.bounds(), width, height);
    size_t segments = pass.prepare(mesh, frame, s).segment_count;  // warm-up: kept lines, scratch
    std::vector<double> wall, cpu;
    for (int i = 0; i < frames; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = cpu_ms();
        segments += pass.prepare(mesh, frame, s).segment_count;
        cpu.push_back(cpu_ms() - c0);
        wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    if (segments == 0) std::printf("  (no segments)\n");
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

// The surface depth drawn on the CPU alone (render/surface/depth_raster.h).
FrameTime median_depth_raster_ms(const render::MeshBuffers& mesh, const render::Camera& camera, int width, int height,
                                 int frames) {
    render::DepthRaster raster;
    const auto frame = render::FrameParams::make(camera, mesh.bounds(), width, height);
    raster.draw(mesh, frame, true);  // warm-up: buffers
    std::vector<double> wall, cpu;
    for (int i = 0; i < frames; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = cpu_ms();
        raster.draw(mesh, frame, true);
        cpu.push_back(cpu_ms() - c0);
        wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

}  // namespace

int main(int argc, char** argv) {
    int width = 1024, height = 768, frames = 20;
    bool line_pass = false, each = false, rtsc = false, msaa = true;
    float detail = 0;
    std::string xf, only;
    std::vector<std::string> meshes;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--each")) each = true;
        else if (!std::strcmp(argv[i], "--line-pass")) line_pass = true;
        else if (!std::strcmp(argv[i], "--rtsc")) rtsc = true;
        else if (!std::strcmp(argv[i], "--no-msaa")) msaa = false;
        else if (!std::strcmp(argv[i], "--xf") && i + 1 < argc) xf = argv[++i];
        else if (!std::strcmp(argv[i], "--only") && i + 1 < argc) only = argv[++i];
        else if (!std::strcmp(argv[i], "--detail") && i + 1 < argc) detail = float(std::atof(argv[++i]));
        else if (!std::strcmp(argv[i], "--size") && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &width, &height);
        else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::max(1, std::atoi(argv[++i]));
        else meshes.push_back(argv[i]);
    }
    if (meshes.empty()) meshes = {"", std::string(KAPPA_SOURCE_DIR) + "/../shared/meshes/bunny-1M.ply"};

    std::unique_ptr<render::HeadlessContext> context;
    try {
        context = render::HeadlessContext::create();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_render: %s\n", e.what());
        return 1;
    }
    std::printf("%s\n%dx%d, median of %d frames\n", context->description().c_str(), width, height, frames);

    render::RenderSettings plain;
    plain.lines = {false, false, false};
    render::RenderSettings lines = plain;
    lines.lines = {true, true, false};
    render::RenderSettings all = lines;
    all.hatching = render::Hatching::Cross;
    render::RenderSettings all_shader = all;  // hatching as the viewer draws it while the view moves
    all_shader.hatch_style = render::HatchStyle::Shader;
    render::RenderSettings lines_unculled = lines;  // what cluster culling saves
    lines_unculled.cull_clusters = false;
    // Where the lines are made (auto: the CPU on software GL, compute passes on a hardware GL 4.3).
    auto on = [](render::RenderSettings s, render::LineExtraction path) {
        s.line_extraction = path;
        return s;
    };
    render::RenderSettings every = lines;  // every kind of render::line_kinds() but the exterior-only silhouette
    for (const render::LineKind& k : render::line_kinds()) every.lines.*(k.flag) = k.name != "silhouette";
    std::vector<Config> configs = {{"lambert", plain}, {"lambert+contours+suggestive", lines},
                                   {"lambert+contours+suggestive+hatching", all},
                                   {"  (contours+suggestive+hatching, shader)", all_shader},
                                   {"  (contours+suggestive, no culling)", lines_unculled},
                                   {"  (contours+suggestive, compute)", on(lines, render::LineExtraction::Compute)},
                                   {"  (contours+suggestive, geometry shader)", on(lines, render::LineExtraction::Gpu)},
                                   {"  (contours+suggestive, CPU extraction)", on(lines, render::LineExtraction::Cpu)},
                                   {"lambert+every line type", every},
                                   {"  (every line type, compute)", on(every, render::LineExtraction::Compute)},
                                   {"  (every line type, geometry shader)", on(every, render::LineExtraction::Gpu)}};
    if (rtsc) {  // rtsc's frame (bench/frames_vs_rtsc.sh): a white unlit surface with contours and suggestive contours
        render::RenderSettings white = lines;
        white.shading = render::Shading::None;
        render::RenderSettings white_gpu = white;
        white_gpu.line_extraction = render::LineExtraction::Gpu;
        configs = {{"white+contours+suggestive", white}, {"  (geometry shader)", white_gpu}};
    }
    if (each)
        for (const render::LineKind& k : render::line_kinds()) {
            render::RenderSettings one = plain;
            one.lines.*(k.flag) = true;
            configs.push_back({k.name.c_str(), one});
        }
    if (!only.empty()) {  // the first configuration (the baseline of the percentages) and those named
        std::vector<Config> kept{configs.front()};
        for (size_t i = 1; i < configs.size(); ++i)
            if (std::string(configs[i].name).find(only) != std::string::npos) kept.push_back(configs[i]);
        configs = kept;
    }
    for (auto& c : configs) c.settings.msaa = false;
    auto with_msaa = msaa ? configs : std::vector<Config>{};
    for (auto& c : with_msaa) c.settings.msaa = true;

    render::Renderer renderer;
    // Frames as the viewer draws them: the compute path never waits for its segment count.
    renderer.set_complete_frames(false);
    renderer.set_line_gpu_timing(true);  // the line passes' GPU times beside each frame's
    const char* path_names[] = {"auto", "compute", "geometry shaders", "CPU"};
    std::printf("lines of auto: %s\n", path_names[int(renderer.line_path(lines))]);
    render::Framebuffer target({width, height, 0, GL_RGBA8, false});
    for (const auto& path : meshes) {
        Mesh mesh;
        try {
            mesh = path.empty() ? make_default_model() : load_mesh(path);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "bench_render: %s\n", e.what());
            return 1;
        }
        const SurfaceFields fields = compute_surface_fields(mesh);
        renderer.set_mesh(mesh, fields, feature_size(mesh, fields));
        render::Camera camera = render::Camera::framing(renderer.mesh()->bounds(), 30.0f, float(width) / float(height));
        if (!xf.empty()) {  // a view saved by kappa view, with rtsc's field of view (as kappa render --xf)
            camera.view = render::read_xf(xf);
            camera.fov_y_deg = render::rtsc_fov_y_deg(width, height);
        }
        if (detail > 0) {
            render::DetailSource source = render::make_detail_source(mesh, fields);
            const render::DetailFields d = render::detail_fields(mesh, source, fields, camera, height, detail);
            renderer.set_mesh(d.mesh, d.fields, d.feature_size, d.fine_normals);
        }
        std::printf("\n%s: %zu vertices, %zu faces, %s\n", path.empty() ? "built-in model" : path.c_str(),
                    mesh.vertex_count(), mesh.face_count(), detail > 0 ? "detail fields" : "raw fields");
        for (auto* set : {&configs, &with_msaa})
            for (auto& c : *set) c.settings.detail = detail;
        for (const auto* set : {&configs, &with_msaa}) {
            std::vector<FrameTime> times;
            for (const auto& c : *set) {
                const FrameTime t = median_frame_ms(renderer, camera, c.settings, target, frames);
                times.push_back(t);
                const FrameTime& base = times.front();
                std::printf("  %-38s %s  wall %8.2f ms (%+4.0f%%)  cpu %8.2f ms (%+4.0f%%)  gpu %8.2f ms"
                            "  (lines: cut %.2f, drawn %.2f)\n",
                            c.name, c.settings.msaa ? "msaa 4x" : "no msaa", t.wall_ms,
                            100.0 * (t.wall_ms / base.wall_ms - 1.0), t.cpu_ms, 100.0 * (t.cpu_ms / base.cpu_ms - 1.0),
                            t.gpu_ms, t.extract_ms, t.draw_ms);
            }
            auto row = [&](const char* name) {
                size_t i = 0;
                while (i < set->size() && std::string((*set)[i].name) != name) ++i;
                return i < set->size() && i > 0 ? int(i) : -1;
            };
            const int every_row = row("lambert+every line type"), lines_row = row("lambert+contours+suggestive");
            if (every_row > 0 && lines_row > 0)
                std::printf("  every line type / contours+suggestive: wall %.2fx, cpu %.2fx\n",
                        times[every_row].wall_ms / times[lines_row].wall_ms, times[every_row].cpu_ms / times[lines_row].cpu_ms);
            if (lines_row > 0)
                std::printf("  contours+suggestive - lambert: wall %+.2f ms\n", times[lines_row].wall_ms - times[0].wall_ms);
            const int shader_row = row("  (contours+suggestive+hatching, shader)");
            if (lines_row > 0 && shader_row > 0)
                std::printf("  shader hatching / contours+suggestive: wall %.2fx\n",
                            times[shader_row].wall_ms / times[lines_row].wall_ms);
            const int every_gs = row("  (every line type, geometry shader)"), lines_gs = row("  (contours+suggestive, geometry shader)");
            if (every_gs > 0 && lines_gs > 0)
                std::printf("  geometry shaders: every line type / contours+suggestive: wall %.2fx\n",
                            times[every_gs].wall_ms / times[lines_gs].wall_ms);
        }
        if (line_pass)
            for (const Config& c : {Config{"contours+suggestive", lines}, Config{"every line type", every}}) {
                render::RenderSettings s = c.settings;
                s.detail = detail;
                const FrameTime t = median_line_pass_ms(*renderer.mesh(), camera, s, width, height, frames);
                std::printf("  CPU line pass alone, %-20s wall %8.2f ms  cpu %8.2f ms\n", c.name, t.wall_ms, t.cpu_ms);
            }
        if (line_pass) {
            const FrameTime t = median_depth_raster_ms(*renderer.mesh(), camera, width, height, frames);
            std::printf("  CPU depth raster alone                    wall %8.2f ms  cpu %8.2f ms\n", t.wall_ms, t.cpu_ms);
        }
    }
    return 0;
}
