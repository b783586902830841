#include "render/renderer.h"

#include "render/frame_params.h"

namespace kappa::render {

Renderer::Renderer() = default;
Renderer::~Renderer() = default;

void Renderer::set_mesh(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                        const std::vector<glm::vec3>& fine_normals) {
    mesh_.reset();
    mesh_ = std::make_unique<MeshBuffers>(mesh, fields, feature_size, fine_normals);
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

void Renderer::ensure_buffers(int width, int height, bool msaa) {
    const int samples = msaa ? 4 : 0;
    if (msaa && !surface_ms_fb_.matches(width, height, samples))
        surface_ms_fb_ = Framebuffer({width, height, samples, GL_RGBA8, true});
    if (!msaa && surface_ms_fb_.id()) surface_ms_fb_ = Framebuffer();
    if (!surface_fb_.matches(width, height, 0)) surface_fb_ = Framebuffer({width, height, 0, GL_RGBA8, true});
    if (!lines_fb_.matches(width, height, 0)) lines_fb_ = Framebuffer({width, height, 0, GL_R8, false});
}

void Renderer::render(const Camera& camera, const RenderSettings& s, const RenderTarget& target) {
    const int w = target.width, h = target.height;
    ensure_buffers(w, h, s.msaa);
    glViewport(0, 0, w, h);

    // 1. Surface, premultiplied over the background.
    const Framebuffer& draw_fb = s.msaa ? surface_ms_fb_ : surface_fb_;
    glBindFramebuffer(GL_FRAMEBUFFER, draw_fb.id());
    const glm::vec4 bg = s.background;
    glClearColor(bg.r * bg.a, bg.g * bg.a, bg.b * bg.a, bg.a);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    FrameParams frame;
    if (mesh_) {
        frame = FrameParams::make(camera, mesh_->bounds(), w, h);
        surface_pass_.draw(*mesh_, frame, s);
    }
    if (s.msaa) resolve(surface_ms_fb_, surface_fb_);

    // 2. Lines as coverage, occlusion-tested against the surface depth.
    glBindFramebuffer(GL_FRAMEBUFFER, lines_fb_.id());
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    if (mesh_ && (s.lines.any() || s.hatching != Hatching::None || s.vectors != 0)) line_pass_.draw(*mesh_, frame, s, surface_fb_.depth_texture());

    // 3. Composite into the target, then the colour bar on top.
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    glViewport(0, 0, w, h);
    compositor_.draw(surface_fb_.color_texture(), lines_fb_.color_texture(), s.line_color);
    if (mesh_ && s.colorbar) colorbar_.draw(s.colormap, mesh_->map_range(s.colormap), w, h, s.background);
    glBindVertexArray(0);
}

Image render_to_image(Renderer& renderer, const Camera& camera, const RenderSettings& settings, int width,
                      int height) {
    Framebuffer target({width, height, 0, GL_RGBA8, false});
    renderer.render(camera, settings, {target.id(), width, height});
    return target.read(settings.background.a < 1.0f);
}

}  // namespace kappa::render
