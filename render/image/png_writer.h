// PNG output with libpng: 8-bit RGBA, fast compression (Z_BEST_SPEED).
#pragma once

#include "render/image/image.h"

#include <string>

namespace kappa::render {

// Writes `image` to `path`; throws std::runtime_error "PATH: reason" when the
// file cannot be written.
void write_png(const std::string& path, const Image& image);

// Reads an 8-bit RGBA (or RGB, grey: expanded to RGBA) PNG; for tests and tools.
Image read_png(const std::string& path);

}  // namespace kappa::render
