// What the browser build has in place of the desktop libraries it lacks
// (web/CMakeLists.txt): PNG files through stb_image_write instead of libpng, and
// no PDF (cairo). The page saves its PNG from the canvas and its SVG through
// render/vector/svg_writer.cpp.
#include "render/image/png_writer.h"
#include "render/vector/vector_drawing.h"

#include <stb/stb_image_write.h>

#include <stdexcept>

namespace kappa::render {

void write_png(const std::string& path, const Image& image) {
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4))
        throw std::runtime_error(path + ": cannot write");
}

Image read_png(const std::string& path) {
    throw std::runtime_error(path + ": reading PNG is not in the browser build");
}

void write_pdf(const std::string& path, const VectorDrawing&) {
    throw std::runtime_error(path + ": PDF output is not in the browser build (use SVG)");
}

}  // namespace kappa::render
