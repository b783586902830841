#include "render/hatching/shader_hatching.h"

#include "render/surface/surface_renderer.h"

namespace kappa::render {

ShaderHatchingPass::ShaderHatchingPass()
    : field_({{GL_VERTEX_SHADER,
               {"common/mesh_attributes.glsl", "hatching/window_directions.glsl", "hatching/hatch_vectors_vert.glsl"}},
              {GL_FRAGMENT_SHADER, {"hatching/hatch_vectors_frag.glsl"}}}),
      strokes_({{GL_VERTEX_SHADER, {"common/fullscreen_vert.glsl"}},
                {GL_FRAGMENT_SHADER, {"hatching/shader_hatching.glsl", "hatching/hatch_strokes_frag.glsl"}}}) {
    glGenVertexArrays(1, &vao_);
}

ShaderHatchingPass::~ShaderHatchingPass() {
    glDeleteVertexArrays(1, &vao_);
    glDeleteFramebuffers(1, &fbo_);
    const GLuint textures[] = {directions_, darkness_};
    glDeleteTextures(2, textures);
    glDeleteRenderbuffers(1, &depth_);
}

namespace {

void nearest_texture(GLuint texture, GLenum internal_format, GLenum format, GLenum type, int width, int height) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal_format), width, height, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace

void ShaderHatchingPass::ensure_targets(int width, int height) {
    if (fbo_ && width == width_ && height == height_) return;
    width_ = width, height_ = height;
    if (!fbo_) {
        glGenFramebuffers(1, &fbo_);
        glGenTextures(1, &directions_);
        glGenTextures(1, &darkness_);
        glGenRenderbuffers(1, &depth_);
    }
    nearest_texture(directions_, GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, width, height);
    nearest_texture(darkness_, GL_R8, GL_RED, GL_UNSIGNED_BYTE, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, directions_, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, darkness_, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
}

void ShaderHatchingPass::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s,
                              GLuint coverage_framebuffer) {
    const int w = int(frame.viewport.x), h = int(frame.viewport.y);
    ensure_targets(w, h);

    // 1. The field of the visible surface.
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, w, h);
    const GLfloat zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    glClearBufferfv(GL_COLOR, 1, zero);
    glDepthMask(GL_TRUE);
    const GLfloat far_depth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    field_.use();
    field_.set("u_mvp", frame.mvp);
    field_.set("u_eye", frame.eye);
    field_.set("u_normal_matrix", frame.normal_matrix);
    field_.set("u_light", camera_light_direction(s, frame));
    field_.set("u_viewport", frame.viewport);
    field_.set("u_feature_size", mesh.feature_size());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    draw_surface_triangles(mesh, frame, back_face_culling_, false);  // the surface pass's visible faces
    glDisable(GL_DEPTH_TEST);

    // 2. The strokes, once a pixel, as line coverage.
    glBindFramebuffer(GL_FRAMEBUFFER, coverage_framebuffer);
    glViewport(0, 0, w, h);
    strokes_.use();
    // Hatching enum order: none, min (along d2), max (along d1), cross; the shader's: none, d1, d2, both.
    const int family[] = {0, 2, 1, 3};
    strokes_.set("u_hatching", family[int(s.hatching)]);
    strokes_.set("u_hatch_spacing", s.hatch_spacing);
    strokes_.set("u_hatch_width", s.hatch_stroke_width);
    strokes_.set("u_directions", 0);
    strokes_.set("u_darkness", 1);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, darkness_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, directions_);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MAX);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

}  // namespace kappa::render
