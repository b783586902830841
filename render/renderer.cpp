#include "render/renderer.h"

#include "render/camera/frame_params.h"
#include "render/hatching/hatch_streamlines.h"

#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <iterator>
#include <limits>
#include <string>

namespace kappa::render {

Renderer::Renderer() {
    const char* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string renderer = name ? name : "";
    software_gl_ = renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos ||
                   renderer.find("SwiftShader") != std::string::npos;
    cpu_line_raster_ = software_gl_;
    cpu_surface_depth_ = software_gl_;
    hatching_in_surface_ = software_gl_;
    if (kGles) {
        // OpenGL ES 3.0 (WebGL2, gles_compat.h): the lines from the CPU drawn as GL quads, which test the
        // surface's depth texture (ES cannot read depth back for the CPU raster); shader hatching in the
        // surface pass (no multiple-target blits).
        cpu_line_raster_ = false;
        cpu_surface_depth_ = false;
        hatching_in_surface_ = true;
    }
}

std::vector<float> Renderer::surface_depth() const {
    if (cpu_depth_) return *cpu_depth_;
    // ES cannot read depth back: the last frame's surface drawn again on the CPU.
    if (kGles) return mesh_ ? depth_raster_.draw(*mesh_, last_frame_, back_face_culling_) : std::vector<float>();
    return surface_fb_.read_depth();
}
Renderer::~Renderer() = default;

LineExtraction Renderer::line_path(const RenderSettings& s) const {
    if (kGles) return LineExtraction::Cpu;  // no geometry or compute shaders in ES 3.0
    const bool compute = line_pass_.compute_available();
    switch (s.line_extraction) {
        case LineExtraction::Cpu: return LineExtraction::Cpu;
        case LineExtraction::Gpu: return LineExtraction::Gpu;
        case LineExtraction::Compute: return compute ? LineExtraction::Compute : LineExtraction::Gpu;
        case LineExtraction::Auto: break;
    }
    if (software_gl_) return LineExtraction::Cpu;
    return compute ? LineExtraction::Compute : LineExtraction::Gpu;
}

void Renderer::set_mesh(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                        const std::vector<glm::vec3>& fine_normals) {
    mesh_.reset();
    mesh_ = std::make_unique<MeshBuffers>(mesh, fields, feature_size, fine_normals);
}

void Renderer::set_mesh(const Mesh& mesh, MeshBuffers::Prepared&& prepared) {
    mesh_.reset();
    mesh_ = std::make_unique<MeshBuffers>(mesh, std::move(prepared));
}

void Renderer::set_mesh(std::unique_ptr<MeshBuffers> buffers) {
    mesh_.reset();
    mesh_ = std::move(buffers);
    if (mesh_) mesh_->finish_upload();  // whatever is left of a landing
}

void Renderer::update_fields(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                             const std::vector<glm::vec3>& fine_normals) {
    if (mesh_) mesh_->update_fields(mesh, fields, feature_size, fine_normals);
}

void Renderer::set_creases(const std::vector<glm::vec3>& end_points) {
    if (mesh_) mesh_->set_creases(end_points);
}

void Renderer::upload_fields(FieldUpload&& prepared) {
    if (mesh_) mesh_->upload(std::move(prepared));
}

void Renderer::begin_field_upload(FieldUpload&& prepared) {
    if (mesh_) mesh_->begin_upload(std::move(prepared));
}

bool Renderer::continue_field_upload(size_t bytes) { return !mesh_ || mesh_->upload_step(bytes); }

void Renderer::ensure_buffers(int width, int height, bool msaa) {
    const int samples = msaa ? 4 : 0;
    if (msaa && !surface_ms_fb_.matches(width, height, samples))
        surface_ms_fb_ = Framebuffer({width, height, samples, GL_RGBA8, true});
    if (!msaa && surface_ms_fb_.id()) surface_ms_fb_ = Framebuffer();
    if (!surface_fb_.matches(width, height, 0)) surface_fb_ = Framebuffer({width, height, 0, GL_RGBA8, true});
    if (!lines_fb_.matches(width, height, 0)) lines_fb_ = Framebuffer({width, height, 0, GL_R8, false});
}

FrameParams Renderer::draw_surface_and_lines(const Camera& camera, const RenderSettings& settings, int w, int h) {
    // An interactive viewer's streamline hatching: the streamlines of this
    // view once traced in the background, the shader's strokes until then
    // (render/hatching/background_hatching.h).
    RenderSettings s = settings;
    HatchViewKey hatch_key;
    const std::vector<Stroke>* traced = nullptr;
    const bool background_streamlines =
        mesh_ && interactive_hatching_ && s.hatching != Hatching::None && !shader_hatching(s);
    if (background_streamlines) {
        const FrameParams view = FrameParams::make(camera, mesh_->bounds(), w, h);
        hatch_key = {view.mvp, view.viewport, camera_light_direction(s, view), s.hatching, s.hatch_spacing,
                     s.hatch_stroke_width, mesh_->fields_version()};
        traced = background_hatching_.strokes_for(hatch_key);
        if (!traced) s.hatch_style = HatchStyle::Shader;
    }
    // Multisampling smooths the surface's edges: a surface the colour of the
    // background has none, and is drawn once per pixel (the same picture).
    // Shader hatching: on software GL drawn by the surface pass per fragment, on a GPU once a pixel
    // from targets the surface pass fills (render/hatching/shader_hatching.h).
    const bool hatch_in_surface = mesh_ && shader_hatching(s) && hatching_in_surface_;
    const bool hatch_targets = mesh_ && shader_hatching(s) && !hatching_in_surface_;
    const bool paper = surface_is_background(s) && !(mesh_ && shader_hatching(s));
    const bool msaa = s.msaa && !paper;
    ensure_buffers(w, h, msaa);
    glViewport(0, 0, w, h);

    // 1. Surface, premultiplied over the background.
    const Framebuffer& draw_fb = msaa ? surface_ms_fb_ : surface_fb_;
    glBindFramebuffer(GL_FRAMEBUFFER, draw_fb.id());
    const glm::vec4 bg = s.background;
    glClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    const LineExtraction path = line_path(s);
    const bool cpu_lines = path == LineExtraction::Cpu;
    const bool any_lines = mesh_ && (s.lines.any() || s.vectors != 0);
    // White paper under lines drawn on the CPU: its depth is all the frame needs of it, drawn on the
    // CPU (the GL's depth buffer is then not cleared: a GL pass that needs it gets the CPU's uploaded).
    const bool depth_on_cpu =
        mesh_ && cpu_surface_depth_ && cpu_line_raster_ && cpu_lines && !msaa && paper;
    glClear(depth_on_cpu ? GL_COLOR_BUFFER_BIT : GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    FrameParams frame;
    if (mesh_) {
        frame = FrameParams::make(camera, mesh_->bounds(), w, h);
        last_frame_ = frame;
        if (any_lines && cpu_lines) line_pass_.begin_cpu_lines(*mesh_, frame, s);  // made while the surface is drawn
        cpu_depth_ = depth_on_cpu ? &depth_raster_.draw(*mesh_, frame, back_face_culling_) : nullptr;
        if (!depth_on_cpu) {
            if (hatch_targets) shader_hatching_.attach(draw_fb.id(), w, h, msaa ? 4 : 0);
            surface_pass_.draw(*mesh_, frame, s,
                               hatch_in_surface ? SurfaceHatching::Strokes
                               : hatch_targets  ? SurfaceHatching::Targets
                                                : SurfaceHatching::None);
            if (hatch_targets) shader_hatching_.detach(draw_fb.id());
        }
    } else {
        cpu_depth_ = nullptr;
    }
    if (msaa) resolve(surface_ms_fb_, surface_fb_);
    std::vector<Stroke> hatching;
    if (background_streamlines) {
        if (traced) {
            hatching = *traced;
        } else if (!view_moving_ && !background_hatching_.pending()) {
            // At rest: this view's field, read back once here, traced on a worker.
            HatchField field = hatch_field_.draw(*mesh_, frame, settings);
            std::vector<glm::vec2> seeds = hatch_seeds_in_view(frame, field);
            background_hatching_.start(hatch_key, std::move(field), std::move(seeds), settings);
        }
    } else if (mesh_ && s.hatching != Hatching::None && !shader_hatching(s)) {
        hatching = hatch_strokes(frame, s);
    }
    drew_streamlines_ = !hatching.empty();
    glViewport(0, 0, w, h);

    // 2. Lines as coverage, occlusion-tested against the surface depth.
    glBindFramebuffer(GL_FRAMEBUFFER, lines_fb_.id());
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    // On software GL the CPU draws its own lines too, and the hatching
    // strokes with them (render/lines/line_raster.h).
    const std::vector<WindowSegment> strokes = stroke_window_segments(hatching, s.hatch_stroke_width, frame), none;
    // On OpenGL ES (no geometry stage for the stroke pass) the CPU line pass draws them as its quads.
    const bool cpu_raster = cpu_line_raster_ && cpu_lines;
    const bool strokes_with_lines = cpu_raster || kGles;
    if (any_lines || (strokes_with_lines && !strokes.empty()))
        ink_ = line_pass_.draw(*mesh_, frame, s, path, surface_fb_.depth_texture(),
                               cpu_line_raster_ ? lines_fb_.color_texture() : 0, strokes_with_lines ? strokes : none,
                               cpu_depth_);
    else
        ink_ = InkArea(), line_pass_.clear_gpu_times();
    if (!strokes_with_lines && !strokes.empty()) {
        stroke_pass_.draw(strokes, frame, surface_fb_.depth_texture());
        ink_.anywhere = true;
    }
    if (hatch_targets) {
        shader_hatching_.draw(frame, s, lines_fb_.id());
        ink_.anywhere = true;
    }

    return frame;
}

void Renderer::render_offscreen(const Camera& camera, const RenderSettings& s, int w, int h) {
    draw_surface_and_lines(camera, s, w, h);
    // 3. The lines blended over the surface in its own framebuffer (no copy).
    glBindFramebuffer(GL_FRAMEBUFFER, surface_fb_.id());
    glViewport(0, 0, w, h);
    compositor_.draw_over(lines_fb_.color_texture(), s.line_color, ink_);
    if (mesh_ && s.colorbar) colorbar_.draw(s.colormap, mesh_->map_range(s.colormap), w, h, s.background);
    glBindVertexArray(0);
}

Image Renderer::render_image(const Camera& camera, const RenderSettings& s, int w, int h) {
    render_offscreen(camera, s, w, h);
    return surface_fb_.read(s.background.a < 1.0f);
}

std::vector<Stroke> Renderer::hatch_strokes(const Camera& camera, const RenderSettings& s, int width, int height) {
    if (!mesh_ || s.hatching == Hatching::None) return {};
    return hatch_strokes(FrameParams::make(camera, mesh_->bounds(), width, height), s);
}

std::vector<glm::vec2> Renderer::hatch_seeds_in_view(const FrameParams& frame, const HatchField& field) const {
    // Surface samples turned towards the eye and not hidden, in their fixed order.
    std::vector<glm::vec2> seeds;
    for (const MeshBuffers::Seed& seed : mesh_->hatch_seeds()) {
        if (glm::dot(seed.normal, frame.eye - seed.position) <= 0) continue;
        const glm::vec4 c = frame.mvp * glm::vec4(seed.position, 1.0f);
        if (c.w <= 0) continue;
        const glm::vec3 ndc = glm::vec3(c) / c.w;
        const glm::vec2 p = (glm::vec2(ndc) * 0.5f + 0.5f) * frame.viewport;
        if (p.x < 0 || p.y < 0 || p.x >= frame.viewport.x || p.y >= frame.viewport.y) continue;
        const float drawn = field.depth[size_t(p.y) * size_t(field.width) + size_t(p.x)];
        const float drawn_distance = field.p32 / (drawn * 2.0f - 1.0f + field.p22);
        if (c.w > drawn_distance * 1.01f) continue;
        seeds.push_back(p);
    }
    return seeds;
}

std::vector<Stroke> Renderer::hatch_strokes(const FrameParams& frame, const RenderSettings& s) {
    const HatchField field = hatch_field_.draw(*mesh_, frame, s);
    return trace_view_hatching(field, hatch_seeds_in_view(frame, field), s);
}

Image render_to_image(Renderer& renderer, const Camera& camera, const RenderSettings& settings, int width,
                      int height) {
    return renderer.render_image(camera, settings, width, height);
}

}  // namespace kappa::render
