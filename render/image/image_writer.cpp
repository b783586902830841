#include "render/image/image_writer.h"

#include "geometry/io/output_file.h"
#include "render/image/png_writer.h"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace kappa::render {

namespace {

void write_jpeg(const std::string& path, const Image& image) {
    std::vector<uint8_t> rgb(size_t(image.width) * size_t(image.height) * 3);
    for (size_t i = 0; i < rgb.size() / 3; ++i) {
        if (image.pixels[4 * i + 3] != 255)
            throw std::runtime_error(path + ": JPEG has no transparency (use .png, or an opaque --background)");
        std::copy_n(&image.pixels[4 * i], 3, &rgb[3 * i]);
    }
    if (!stbi_write_jpg(path.c_str(), image.width, image.height, 3, rgb.data(), 95))
        throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
}

}  // namespace

std::optional<ImageFormat> image_format_for(const std::string& path) {
    const std::string ext = io::lower_extension(path);
    if (ext == "png") return ImageFormat::Png;
    if (ext == "jpg" || ext == "jpeg") return ImageFormat::Jpeg;
    return std::nullopt;
}

void write_image(const std::string& path, const Image& image) {
    const auto format = image_format_for(path);
    if (!format) throw std::runtime_error(path + ": unknown image format (use .png, .jpg or .jpeg)");
    if (*format == ImageFormat::Png) write_png(path, image);
    else write_jpeg(path, image);
}

}  // namespace kappa::render
