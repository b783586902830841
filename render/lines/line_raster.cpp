#include "render/lines/line_raster.h"

#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace kappa::render {

namespace {

constexpr int kBandRows = 16;

float camera_distance(float window_depth, glm::vec2 dp) { return dp.y / (window_depth * 2.0f - 1.0f + dp.x); }

// Narrows [lo, hi] to the x where lo_c <= u.(x, y) - u.a <= hi_c on row y.
void clip_row(glm::vec2 u, glm::vec2 a, float lo_c, float hi_c, float y, float& lo, float& hi) {
    const float base = glm::dot(u, a) - u.y * y;  // u.x x must lie in [lo_c + base, hi_c + base]
    if (std::fabs(u.x) < 1e-12f) {
        if (-base < lo_c || -base > hi_c) lo = 1e30f, hi = -1e30f;  // the row misses the slab: empty
        return;
    }
    float x0 = (lo_c + base) / u.x, x1 = (hi_c + base) / u.x;
    if (x0 > x1) std::swap(x0, x1);
    lo = std::max(lo, x0), hi = std::min(hi, x1);
}

// A segment's constants, computed once, not per pixel.
struct Shape {
    glm::vec2 a, ab;
    float len2, inv_len2, len;
    glm::vec2 dir, nrm;  // unit along and across the segment ((1, 0) along a point)
    float width;         // pixels
    float reach;         // w/2 + 1/2: lines_frag.glsl gives no coverage farther from the centre line
};

float width_of(const WindowSegment& s, const LineRasterParams& o) { return s.width > 0.0f ? s.width : o.line_width; }

Shape shape_of(const WindowSegment& s, const LineRasterParams& o) {
    Shape g;
    g.a = glm::vec2(s.a), g.ab = glm::vec2(s.b) - g.a;
    g.len2 = glm::dot(g.ab, g.ab);
    g.inv_len2 = g.len2 > 1e-12f ? 1.0f / g.len2 : 0.0f;
    g.len = std::sqrt(g.len2);
    g.dir = g.len > 1e-6f ? g.ab / g.len : glm::vec2(1, 0);
    g.nrm = glm::vec2(-g.dir.y, g.dir.x);
    g.width = width_of(s, o);
    g.reach = 0.5f * g.width + 0.5f;
    return g;
}

// lines_frag.glsl for one pixel centre p (not on the surface): the coverage to max-blend, 0 for none.
float pixel_ink(const WindowSegment& s, const Shape& g, glm::vec2 p, const std::vector<float>& depth,
                const LineRasterParams& o) {
    const glm::vec2 pa = p - g.a;
    const float along = glm::dot(pa, g.ab) * g.inv_len2;
    const float t = along > 0.0f ? std::min(along, 1.0f) : 0.0f;  // clamp, NaN (a segment beyond float) to 0
    const glm::vec2 from_q = pa - t * g.ab;  // p - q, q the closest point of the centre line
    const float d2 = glm::dot(from_q, from_q);
    if (d2 >= g.reach * g.reach) return 0;  // coverage reach - |p - q| <= 0
    const float coverage = std::min(g.reach - std::sqrt(d2), 1.0f);
    const glm::vec2 q = p - from_q;
    const glm::ivec2 size(o.width, o.height);
    auto depth_at = [&](glm::ivec2 c) { return depth[size_t(c.y) * size_t(o.width) + size_t(c.x)]; };
    // The texel holding x, clamped to the image (floor by truncation of x >= 0: no libm call per pixel).
    auto texel = [&](glm::vec2 x) {
        const float cx = x.x > 0.0f ? std::min(x.x, float(size.x - 1)) : 0.0f;  // NaN to 0
        const float cy = x.y > 0.0f ? std::min(x.y, float(size.y - 1)) : 0.0f;
        return glm::ivec2(int(cx), int(cy));
    };
    if (s.on_surface && depth_at(texel(p)) == 1.0f) return 0;
    if (s.exterior_only) {
        const glm::vec2 side = g.len2 > 1e-12f ? glm::vec2(-g.ab.y, g.ab.x) / g.len : glm::vec2(1, 0);
        const float reach = 0.5f * g.width + 2.0f;
        if (depth_at(texel(q + side * reach)) < 1.0f && depth_at(texel(q - side * reach)) < 1.0f) return 0;
    }
    const glm::ivec2 qi = texel(q);
    const float line_distance = camera_distance(s.a.z + (s.b.z - s.a.z) * t, o.depth_params);
    const float centre = depth_at(qi);
    float shade = 1.0f;
    if (centre < 1.0f && line_distance > camera_distance(centre, o.depth_params) + s.tolerance) {
        float farthest = centre;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                farthest = std::max(farthest, depth_at(glm::clamp(qi + glm::ivec2(dx, dy), glm::ivec2(0), size - 1)));
        if (farthest < 1.0f && line_distance > camera_distance(farthest, o.depth_params) + s.tolerance) {
            if (!o.hidden_lines || s.on_surface || std::fmod(t * g.len, 10.0f) > 6.0f) return 0;
            shade = 0.35f;
        }
    }
    return shade * coverage * (s.alpha.x + (s.alpha.y - s.alpha.x) * t);
}

// The rows [first_row, end_row) of one segment's capsule.
void draw_rows(const WindowSegment& s, int first_row, int end_row, const std::vector<float>& depth,
               const LineRasterParams& o, uint8_t* coverage) {
    const Shape g = shape_of(s, o);
    for (int y = first_row; y < end_row; ++y) {
        const float py = float(y) + 0.5f;
        // The row's span of the capsule within r of the centre line (convex: one
        // interval), the union of the band along the segment and the end discs;
        // the pixels of the quad outside it get no coverage.
        float lo = -1e30f, hi = 1e30f;
        clip_row(g.nrm, g.a, -g.reach, g.reach, py, lo, hi);
        clip_row(g.dir, g.a, 0.0f, g.len, py, lo, hi);
        if (!(lo <= hi)) lo = 1e30f, hi = -1e30f;  // the band misses the row: only the discs remain
        for (const glm::vec2 end : {glm::vec2(s.a), glm::vec2(s.b)}) {
            const float dy = py - end.y, h2 = g.reach * g.reach - dy * dy;
            if (!(h2 > 0.0f)) continue;
            const float h = std::sqrt(h2);
            lo = std::min(lo, end.x - h), hi = std::max(hi, end.x + h);
        }
        if (!(lo <= hi)) continue;
        lo = std::max(lo, -1.0f), hi = std::min(hi, float(o.width) + 1.0f);  // in range for int
        const int x0 = std::max(0, int(std::ceil(lo - 0.5f))), x1 = std::min(o.width - 1, int(std::floor(hi - 0.5f)));
        uint8_t* row = coverage + size_t(y) * size_t(o.width);
        for (int x = x0; x <= x1; ++x) {
            const float ink = pixel_ink(s, g, glm::vec2(float(x) + 0.5f, py), depth, o);
            if (ink <= 0.0f) continue;
            const uint8_t value = uint8_t(std::min(ink, 1.0f) * 255.0f + 0.5f);  // unorm8, rounded
            row[x] = std::max(row[x], value);
        }
    }
}

}  // namespace

void rasterize_lines(const std::vector<WindowSegment>& segments, const std::vector<float>& depth,
                     const LineRasterParams& o, std::vector<uint8_t>& coverage) {
    const size_t pixels = size_t(std::max(o.width, 0)) * size_t(std::max(o.height, 0));
    if (coverage.size() != pixels) coverage.assign(pixels, 0);
    if (pixels == 0 || depth.size() != pixels) return;
    // Each segment's rows, and the segments of each band of rows.
    const int bands = (o.height + kBandRows - 1) / kBandRows;
    std::vector<std::vector<uint32_t>> in_band(static_cast<size_t>(bands));
    std::vector<glm::ivec2> rows(segments.size());
    for (size_t i = 0; i < segments.size(); ++i) {
        const WindowSegment& s = segments[i];
        if (!std::isfinite(s.a.x + s.a.y + s.a.z + s.b.x + s.b.y + s.b.z + s.alpha.x + s.alpha.y))
            continue;  // never drawn (the GL would drop it too)
        const float r = 0.5f * width_of(s, o) + 0.5f;
        const float y_lo = std::min(s.a.y, s.b.y) - r, y_hi = std::max(s.a.y, s.b.y) + r;
        if (!(y_hi >= 0.0f && y_lo <= float(o.height))) continue;
        rows[i] = {std::max(0, int(std::floor(y_lo))), std::min(o.height, int(std::ceil(y_hi)) + 1)};
        for (int b = rows[i].x / kBandRows; b < bands && b * kBandRows < rows[i].y; ++b) in_band[size_t(b)].push_back(uint32_t(i));
    }
    parallel_for_dynamic(size_t(bands), [&](size_t b) {
        const int band_lo = int(b) * kBandRows, band_hi = std::min(o.height, band_lo + kBandRows);
        for (uint32_t i : in_band[b])
            draw_rows(segments[i], std::max(band_lo, rows[i].x), std::min(band_hi, rows[i].y), depth, o, coverage.data());
    });
}

std::vector<glm::ivec4> inked_rectangles(const std::vector<uint8_t>& coverage, int width, int height, int cell) {
    std::vector<glm::ivec4> rects;
    if (width <= 0 || height <= 0 || coverage.size() < size_t(width) * size_t(height)) return rects;
    const int columns = (width + cell - 1) / cell;
    std::vector<uint8_t> inked(static_cast<size_t>(columns));
    for (int y0 = 0; y0 < height; y0 += cell) {
        const int rows = std::min(cell, height - y0);
        std::fill(inked.begin(), inked.end(), uint8_t(0));
        for (int y = y0; y < y0 + rows; ++y) {
            const uint8_t* row = coverage.data() + size_t(y) * size_t(width);
            int x = 0;
            for (; x + 8 <= width; x += 8) {  // eight pixels at a time: most are blank
                uint64_t word;
                std::memcpy(&word, row + x, 8);
                if (word)
                    for (int i = x; i < x + 8; ++i) inked[size_t(i / cell)] |= uint8_t(row[i] != 0);
            }
            for (; x < width; ++x) inked[size_t(x / cell)] |= uint8_t(row[x] != 0);
        }
        for (int c = 0; c < columns;) {
            if (!inked[size_t(c)]) {
                ++c;
                continue;
            }
            const int first = c;
            while (c < columns && inked[size_t(c)]) ++c;
            const int x0 = first * cell, x1 = std::min(width, c * cell);
            rects.push_back({x0, y0, x1 - x0, rows});
        }
    }
    return rects;
}

}  // namespace kappa::render
