#include "app/viewer/screenshot.h"

#include "render/gl/gl.h"

#include <cstring>

namespace kappa::viewer {

render::Image read_window(int width, int height) {
    render::Image image(width, height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    // OpenGL's rows start at the bottom; PNG's at the top.
    const size_t row = size_t(width) * 4;
    std::vector<uint8_t> tmp(row);
    for (int y = 0; y < height / 2; ++y) {
        uint8_t* a = &image.pixels[size_t(y) * row];
        uint8_t* b = &image.pixels[size_t(height - 1 - y) * row];
        std::memcpy(tmp.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, tmp.data(), row);
    }
    for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;  // the window is opaque
    return image;
}

}  // namespace kappa::viewer
