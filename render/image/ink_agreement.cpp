#include "render/image/ink_agreement.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace kappa::render {

bool is_ink(const Rgba& c) { return std::min({c.r, c.g, c.b}) < 128; }

size_t count_ink(const Image& image) {
    size_t n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) n += is_ink(image.at(x, y));
    return n;
}

double ink_within(const Image& a, const Image& b, float radius) {
    if (a.width != b.width || a.height != b.height) throw std::invalid_argument("ink_within: images differ in size");
    const int w = a.width, h = a.height, r = int(std::floor(radius));
    std::vector<uint8_t> ink_b(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ink_b[size_t(y) * size_t(w) + size_t(x)] = is_ink(b.at(x, y));
    size_t total = 0, near = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!is_ink(a.at(x, y))) continue;
            ++total;
            bool found = false;
            for (int dy = -r; dy <= r && !found; ++dy)
                for (int dx = -r; dx <= r && !found; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= w || yy >= h || float(dx * dx + dy * dy) > radius * radius) continue;
                    found = ink_b[size_t(yy) * size_t(w) + size_t(xx)];
                }
            near += found;
        }
    return total ? double(near) / double(total) : 1.0;
}

}  // namespace kappa::render
