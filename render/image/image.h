// An 8-bit RGBA image in memory, rows from top to bottom (PNG order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace kappa::render {

using std::size_t;

struct Rgba {
    uint8_t r = 0, g = 0, b = 0, a = 0;
};

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;  // width * height * 4 bytes, top row first

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h) * 4, 0) {}

    // (x, y) with y = 0 the top row.
    Rgba at(int x, int y) const {
        const uint8_t* p = &pixels[(size_t(y) * size_t(width) + size_t(x)) * 4];
        return {p[0], p[1], p[2], p[3]};
    }
};

}  // namespace kappa::render
