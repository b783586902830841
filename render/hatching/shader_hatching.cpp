#include "render/hatching/shader_hatching.h"

namespace kappa::render {

namespace {

constexpr GLenum kDirectionsFormat = GL_RGBA16F, kDarknessFormat = GL_R8;

void nearest_texture(GLuint texture, GLenum internal_format, GLenum format, GLenum type, int width, int height) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal_format), width, height, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void multisampled_storage(GLuint renderbuffer, GLenum internal_format, int samples, int width, int height) {
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, internal_format, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
}

}  // namespace

void set_hatching_uniforms(ShaderProgram& p, const RenderSettings& s) {
    // Hatching enum order: none, min (along d2), max (along d1), cross; the shader's: none, d1, d2, both.
    const int family[] = {0, 2, 1, 3};
    p.set("u_hatching", family[int(s.hatching)]);
    p.set("u_hatch_spacing", s.hatch_spacing);
    p.set("u_hatch_width", s.hatch_stroke_width);
}

ShaderHatchingPass::ShaderHatchingPass()
    : strokes_({{GL_VERTEX_SHADER, {"common/fullscreen_vert.glsl"}},
                {GL_FRAGMENT_SHADER, {"hatching/shader_hatching.glsl", "hatching/hatch_strokes_frag.glsl"}}}) {
    glGenVertexArrays(1, &vao_);
    glGenTextures(1, &directions_);
    glGenTextures(1, &darkness_);
    glGenRenderbuffers(1, &ms_directions_);
    glGenRenderbuffers(1, &ms_darkness_);
    glGenFramebuffers(1, &resolve_fbo_);
}

ShaderHatchingPass::~ShaderHatchingPass() {
    glDeleteVertexArrays(1, &vao_);
    const GLuint textures[] = {directions_, darkness_};
    glDeleteTextures(2, textures);
    const GLuint renderbuffers[] = {ms_directions_, ms_darkness_};
    glDeleteRenderbuffers(2, renderbuffers);
    glDeleteFramebuffers(1, &resolve_fbo_);
}

void ShaderHatchingPass::attach(GLuint surface_framebuffer, int width, int height, int samples) {
    if (width != width_ || height != height_ || samples != samples_) {
        nearest_texture(directions_, kDirectionsFormat, GL_RGBA, GL_HALF_FLOAT, width, height);
        nearest_texture(darkness_, kDarknessFormat, GL_RED, GL_UNSIGNED_BYTE, width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, directions_, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, darkness_, 0);
        if (samples > 0) {
            multisampled_storage(ms_directions_, kDirectionsFormat, samples, width, height);
            multisampled_storage(ms_darkness_, kDarknessFormat, samples, width, height);
        }
        width_ = width, height_ = height, samples_ = samples;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, surface_framebuffer);
    // The targets stay attached from frame to frame (changing a framebuffer's attachments every
    // frame makes the driver check it again): attached only when this framebuffer lacks them.
    const GLuint directions = samples > 0 ? ms_directions_ : directions_;
    GLint attached = 0;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                          &attached);
    if (GLuint(attached) != directions) {
        if (samples > 0) {
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, ms_directions_);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_RENDERBUFFER, ms_darkness_);
        } else {
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, directions_, 0);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, darkness_, 0);
        }
    }
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glDrawBuffers(3, buffers);
    const GLfloat zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 1, zero);
    glClearBufferfv(GL_COLOR, 2, zero);
}

void ShaderHatchingPass::detach(GLuint surface_framebuffer) {
    if (samples_ > 0) {
        // Resolve: attachment 1 -> directions_, attachment 2 -> darkness_ (averaged samples).
        glBindFramebuffer(GL_READ_FRAMEBUFFER, surface_framebuffer);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
        for (GLenum i = 0; i < 2; ++i) {
            glReadBuffer(GL_COLOR_ATTACHMENT1 + i);
            glDrawBuffer(GL_COLOR_ATTACHMENT0 + i);
            glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        }
    }
    // The framebuffer draws into and reads from attachment 0 alone again; the targets stay attached.
    glBindFramebuffer(GL_FRAMEBUFFER, surface_framebuffer);
    const GLenum buffer = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &buffer);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
}

void ShaderHatchingPass::draw(const FrameParams& frame, const RenderSettings& s, GLuint coverage_framebuffer) {
    glBindFramebuffer(GL_FRAMEBUFFER, coverage_framebuffer);
    glViewport(0, 0, int(frame.viewport.x), int(frame.viewport.y));
    strokes_.use();
    set_hatching_uniforms(strokes_, s);
    strokes_.set("u_directions", 0);
    strokes_.set("u_darkness", 1);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, darkness_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, directions_);
    glDisable(GL_DEPTH_TEST);
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
