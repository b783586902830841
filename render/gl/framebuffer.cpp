#include "render/gl/framebuffer.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

namespace kappa::render {

namespace {

GLuint make_texture(GLenum internal_format, GLenum format, GLenum type, int w, int h) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal_format), w, h, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

GLuint make_renderbuffer(GLenum internal_format, int samples, int w, int h) {
    GLuint r = 0;
    glGenRenderbuffers(1, &r);
    glBindRenderbuffer(GL_RENDERBUFFER, r);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, internal_format, w, h);
    return r;
}

}  // namespace

Framebuffer::Framebuffer(const Spec& spec) : spec_(spec) {
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    if (spec.width <= 0 || spec.height <= 0 || spec.width > max_size || spec.height > max_size)
        throw std::runtime_error("image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                                 " is not supported (at most " + std::to_string(max_size) + " pixels a side)");
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    const bool ms = spec.samples > 1;
    if (spec.color_format) {
        if (ms) {
            color_ = make_renderbuffer(spec.color_format, spec.samples, spec.width, spec.height);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
        } else {
            const GLenum format = spec.color_format == GL_R8 ? GL_RED : GL_RGBA;
            color_ = make_texture(spec.color_format, format, GL_UNSIGNED_BYTE, spec.width, spec.height);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
        }
    }
    if (spec.depth) {
        if (ms) {
            depth_ = make_renderbuffer(GL_DEPTH_COMPONENT24, spec.samples, spec.width, spec.height);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
        } else {
            depth_ = make_texture(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, spec.width, spec.height);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
        }
    }
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        release();
        throw std::runtime_error("cannot create a " + std::to_string(spec.width) + "x" +
                                 std::to_string(spec.height) + " framebuffer (status 0x" +
                                 [&] { char b[16]; std::snprintf(b, sizeof b, "%x", status); return std::string(b); }() + ")");
    }
}

Framebuffer::~Framebuffer() { release(); }

Framebuffer& Framebuffer::operator=(Framebuffer&& o) noexcept {
    if (this != &o) {
        release();
        spec_ = o.spec_;
        std::swap(fbo_, o.fbo_);
        std::swap(color_, o.color_);
        std::swap(depth_, o.depth_);
    }
    return *this;
}

void Framebuffer::release() {
    const bool ms = spec_.samples > 1;
    if (color_) ms ? glDeleteRenderbuffers(1, &color_) : glDeleteTextures(1, &color_);
    if (depth_) ms ? glDeleteRenderbuffers(1, &depth_) : glDeleteTextures(1, &depth_);
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    fbo_ = color_ = depth_ = 0;
}

Image Framebuffer::read(bool unpremultiply) const {
    const int w = spec_.width, h = spec_.height;
    Image image(w, h);
    std::vector<uint8_t> raw(image.pixels.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
    const size_t row = size_t(w) * 4;
    for (int y = 0; y < h; ++y)  // GL's first row is the bottom one
        std::copy_n(&raw[size_t(h - 1 - y) * row], row, &image.pixels[size_t(y) * row]);
    if (unpremultiply)
        for (size_t i = 0; i < image.pixels.size(); i += 4) {
            const unsigned a = image.pixels[i + 3];
            if (a == 0 || a == 255) continue;
            for (int c = 0; c < 3; ++c)
                image.pixels[i + c] = uint8_t(std::min(255u, (image.pixels[i + c] * 255u + a / 2) / a));
        }
    return image;
}

std::vector<float> Framebuffer::read_depth() const {
    std::vector<float> depth(size_t(spec_.width) * size_t(spec_.height));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, spec_.width, spec_.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    return depth;
}

void resolve(const Framebuffer& from, const Framebuffer& to) {
    const int w = from.spec().width, h = from.spec().height;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to.id());
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

}  // namespace kappa::render
