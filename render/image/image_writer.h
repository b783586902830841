// Writes an image in the format its file name says: .png (libpng, RGBA) or
// .jpg/.jpeg (stb_image_write, quality 95, RGB: a transparent background
// has no JPEG form and is refused).
#pragma once

#include "render/image/image.h"

#include <optional>
#include <string>

namespace kappa::render {

enum class ImageFormat { Png, Jpeg };

// From the file's extension, any case; nullopt for anything else.
std::optional<ImageFormat> image_format_for(const std::string& path);

// Throws std::runtime_error "PATH: reason" (unknown extension, unwritable
// file, transparency in a JPEG).
void write_image(const std::string& path, const Image& image);

}  // namespace kappa::render
