// Framebuffer objects: the renderer's internal buffers (multisampled surface,
// resolved colour + depth textures, line coverage) and the offscreen target
// of headless rendering, with readback to an Image.
#pragma once

#include "render/gl/gl.h"
#include "render/image/image.h"

#include <vector>

namespace kappa::render {

class Framebuffer {
public:
    struct Spec {
        int width = 0, height = 0;
        int samples = 0;              // > 1: multisampled renderbuffers
        GLenum color_format = GL_RGBA8;  // 0: no colour attachment
        bool depth = false;           // DEPTH_COMPONENT24 attachment
    };

    Framebuffer() = default;
    // Throws std::runtime_error when the framebuffer is incomplete (e.g. too
    // large for the implementation).
    explicit Framebuffer(const Spec& spec);
    ~Framebuffer();
    Framebuffer(Framebuffer&& o) noexcept { *this = std::move(o); }
    Framebuffer& operator=(Framebuffer&& o) noexcept;
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;

    GLuint id() const { return fbo_; }
    const Spec& spec() const { return spec_; }
    bool matches(int width, int height, int samples) const {
        return fbo_ && spec_.width == width && spec_.height == height && spec_.samples == samples;
    }
    // Single-sampled framebuffers attach textures (for sampling in later passes).
    GLuint color_texture() const { return color_; }
    GLuint depth_texture() const { return depth_; }

    // Reads the colour attachment as 8-bit RGBA, top row first. With
    // `unpremultiply`, colours are divided by alpha (PNG stores straight alpha).
    Image read(bool unpremultiply) const;
    // Reads the depth attachment (window depth in [0, 1], 1 = background),
    // bottom row first as in GL window coordinates. Single-sampled only.
    std::vector<float> read_depth() const;

private:
    void release();
    Spec spec_;
    GLuint fbo_ = 0, color_ = 0, depth_ = 0;  // textures, or renderbuffers when multisampled
};

// Copies colour and depth of a multisampled framebuffer into a single-sampled
// one of the same size (the MSAA resolve).
void resolve(const Framebuffer& from, const Framebuffer& to);

}  // namespace kappa::render
