#include "render/surface/depth_raster.h"

#include "geometry/parallel/lanes.h"
#include "geometry/parallel/parallel.h"
#include "render/surface/surface_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace kappa::render {

namespace {

enum class Cull { None, Back, Front };

// Faces [first, first + count) drawn with one culling into one rectangle
// (x0, y0, x1, y1: pixels, the end exclusive).
struct Piece {
    uint32_t first, count;
    Cull cull;
    glm::ivec4 rect;
};

using WindowVertex = glm::vec3;  // x, y: pixels; z: window depth

struct Target {
    float* depth;
    int width;
    glm::ivec4 rect;    // where it may draw (x0, y0, x1, y1, the end exclusive)
    glm::ivec4* drawn;  // grown to hold every pixel drawn
};

// Whether pixel centres exactly on the directed edge d (interior on its
// left) belong to the triangle: its top and left edges (y up).
bool owns_edge(float dx, float dy) { return dy < 0.0f || (dy == 0.0f && dx < 0.0f); }

// An edge's function E(p) = d x (p - from), > 0 on its left, evaluated from
// its lexicographically smaller end whichever way the triangle runs along it
// (then negated): the two triangles on an edge get opposite values bit for
// bit, so with owns_edge a pixel centre on it is filled exactly once.
struct Edge {
    float ax, ay, dx, dy, sign;  // canonical start and direction, sign +-1 to this triangle's direction
    bool own;
    Edge(const WindowVertex& from, const WindowVertex& to) {
        own = owns_edge(to.x - from.x, to.y - from.y);
        const bool forward = from.x < to.x || (from.x == to.x && from.y < to.y);
        const WindowVertex& s = forward ? from : to;
        const WindowVertex& e = forward ? to : from;
        ax = s.x, ay = s.y, dx = e.x - s.x, dy = e.y - s.y, sign = forward ? 1.0f : -1.0f;
    }
    float row(float py) const { return dx * (py - ay); }                            // per row
    float at(float row_part, float px) const { return sign * (row_part - dy * (px - ax)); }  // per pixel
    bool inside(float e) const { return e > 0.0f || (e == 0.0f && own); }
};

// floor and ceiling of v, |v| < 2^31, without a library call (x86-64's
// baseline has no rounding instruction: std::floor is a call, per triangle).
int floor_int(float v) {
    const int i = int(v);
    return float(i) > v ? i - 1 : i;
}
int ceil_int(float v) {
    const int i = int(v);
    return float(i) < v ? i + 1 : i;
}

// One triangle, counter-clockwise in the window, into t with GL_LESS.
void fill(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, float area, const Target& t) {
    const float min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
    const float min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
    // Clipped to the view volume: within a pixel of the viewport.
    const int x0 = std::max(t.rect.x, ceil_int(min_x - 0.5f)), x1 = std::min(t.rect.z - 1, floor_int(max_x - 0.5f));
    const int y0 = std::max(t.rect.y, ceil_int(min_y - 0.5f)), y1 = std::min(t.rect.w - 1, floor_int(max_y - 0.5f));
    if (x0 > x1 || y0 > y1) return;
    glm::ivec4& drawn = *t.drawn;
    drawn = {std::min(drawn.x, x0), std::min(drawn.y, y0), std::max(drawn.z, x1 + 1), std::max(drawn.w, y1 + 1)};
    const Edge edges[3] = {Edge(b, c), Edge(c, a), Edge(a, b)};  // opposite a, b, c: weights of a, b, c
    const float inv_area = 1.0f / area, dzb = b.z - a.z, dzc = c.z - a.z;
    for (int y = y0; y <= y1; ++y) {
        const float py = float(y) + 0.5f;
        const float r[3] = {edges[0].row(py), edges[1].row(py), edges[2].row(py)};
        // The row's pixels inside every edge's half plane, widened by a pixel
        // (the exact test below decides): E = sign (r - dy (px - ax)).
        float lo = float(x0), hi = float(x1);
        for (int k = 0; k < 3 && x1 - x0 > 16; ++k) {  // narrow triangles: the box is as cheap
            const float slope = -edges[k].sign * edges[k].dy;  // dE/dpx
            if (slope == 0.0f) continue;
            const float root = edges[k].ax + r[k] / edges[k].dy;  // E = 0
            if (!(root > lo - 2.0f && root < hi + 2.0f)) {  // beyond the box (or NaN): no narrowing, or none inside
                if (slope > 0.0f ? root >= hi + 2.0f : root <= lo - 2.0f) lo = 1.0f, hi = 0.0f;
                continue;
            }
            if (slope > 0.0f) lo = std::max(lo, float(floor_int(root - 0.5f) - 1));
            else hi = std::min(hi, float(ceil_int(root - 0.5f) + 1));
        }
        if (!(lo <= hi)) continue;
        float* row = t.depth + size_t(y) * size_t(t.width);
        int x = int(lo);
        // Four pixels at a time (geometry/parallel/lanes.h: the same operations, the same bits).
        using lanes::Lanes;
        using Mask = int __attribute__((vector_size(16)));
        // Four lanes while they stay within the row (lanes past hi are written back unchanged:
        // the buffer is this range's own).
        const int last = int(hi);
        for (; x <= last && x + 3 < t.width; x += 4) {
            const Lanes px = float(x) + Lanes{0.5f, 1.5f, 2.5f, 3.5f};
            Lanes e[3];
            Mask in = Mask{x, x + 1, x + 2, x + 3} <= last;
            for (int k = 0; k < 3; ++k) {
                const Edge& g = edges[k];
                e[k] = g.sign * (r[k] - g.dy * (px - g.ax));
                in &= (e[k] > 0.0f) | ((e[k] == 0.0f) & (Mask{} - int(g.own)));
            }
            const Lanes z = a.z + (e[1] * inv_area) * dzb + (e[2] * inv_area) * dzc;
            Lanes d;
            std::memcpy(&d, row + x, sizeof d);
            d = (in & (z < d)) ? z : d;
            std::memcpy(row + x, &d, sizeof d);
        }
        for (; x <= int(hi); ++x) {
            const float px = float(x) + 0.5f;
            const float e0 = edges[0].at(r[0], px), e1 = edges[1].at(r[1], px), e2 = edges[2].at(r[2], px);
            if (!(edges[0].inside(e0) && edges[1].inside(e1) && edges[2].inside(e2))) continue;
            const float z = a.z + (e1 * inv_area) * dzb + (e2 * inv_area) * dzc;
            if (z < row[x]) row[x] = z;
        }
    }
}

// Outside bits of a clip-space point for the planes -w <= x, y, z <= w.
unsigned outside(const glm::vec4& v) {
    return unsigned(v.x < -v.w) | unsigned(v.x > v.w) << 1 | unsigned(v.y < -v.w) << 2 | unsigned(v.y > v.w) << 3 |
           unsigned(v.z < -v.w) << 4 | unsigned(v.z > v.w) << 5;
}

// Signed distance to plane k of the view volume (>= 0 inside).
float plane_distance(const glm::vec4& v, int k) {
    const float c = k < 2 ? v.x : (k < 4 ? v.y : v.z);
    return k % 2 == 0 ? v.w + c : v.w - c;
}

// The polygon of a triangle clipped to the view volume (Sutherland and
// Hodgman 1974): at most 9 vertices.
int clip_polygon(const glm::vec4 (&in)[3], glm::vec4 (&out)[9]) {
    glm::vec4 a[9], b[9];
    int n = 3;
    std::copy(in, in + 3, a);
    for (int k = 0; k < 6 && n > 0; ++k) {
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const glm::vec4 &p = a[i], &q = a[(i + 1) % n];
            const float dp = plane_distance(p, k), dq = plane_distance(q, k);
            if (dp >= 0) b[m++] = p;
            if ((dp >= 0) != (dq >= 0) && m < 9) b[m++] = p + (q - p) * (dp / (dp - dq));
        }
        n = m;
        std::copy(b, b + n, a);
    }
    std::copy(a, a + n, out);
    return n;
}

}  // namespace

const std::vector<float>& DepthRaster::draw(const MeshBuffers& mesh, const FrameParams& frame, bool cull) {
    const int width = int(frame.viewport.x), height = int(frame.viewport.y);
    const size_t pixels = size_t(width) * size_t(height);
    if (width != width_ || height != height_) buffers_.clear(), drawn_.clear(), width_ = width, height_ = height;
    // One buffer for each of up to four ranges of faces (one a thread), the first the result.
    const size_t max_slots = std::clamp<size_t>(thread_count(), 1, 4);
    while (buffers_.size() < max_slots) buffers_.emplace_back(pixels, 1.0f), drawn_.push_back(glm::ivec4(0));
    // Back to 1 where the last frame drew.
    auto clear = [&](size_t s) {
        const glm::ivec4 r = drawn_[s];
        for (int y = r.y; y < r.w; ++y)
            std::fill_n(buffers_[s].begin() + std::ptrdiff_t(size_t(y) * size_t(width) + size_t(r.x)), r.z - r.x, 1.0f);
        drawn_[s] = {width, height, 0, 0};  // empty
    };
    clear(0);
    std::vector<float>& depth = buffers_[0];
    const Mesh& m = mesh.cpu_mesh();
    if (pixels == 0 || m.face_count() == 0) return depth;

    // What draw_surface_triangles sends.
    const SurfaceTriangles triangles = surface_triangles(mesh, frame, cull);
    std::vector<Piece> pieces;
    const glm::ivec4 whole(0, 0, width, height);
    for (const FaceRun& r : triangles.front)
        pieces.push_back({r.first, r.count, triangles.cull ? Cull::Back : Cull::None, whole});
    const glm::ivec4 h = triangles.holes;
    const glm::ivec4 holes(std::max(h.x, 0), std::max(h.y, 0), std::min(h.x + h.z, width), std::min(h.y + h.w, height));
    for (const FaceRun& r : triangles.back) pieces.push_back({r.first, r.count, Cull::Front, holes});
    size_t faces = 0;
    for (const Piece& p : pieces) faces += p.count;
    if (faces == 0) return depth;

    const float half_w = 0.5f * float(width), half_h = 0.5f * float(height);
    auto to_window = [&](const glm::vec4& c) {
        const float inv_w = 1.0f / c.w;
        return WindowVertex{(c.x * inv_w + 1.0f) * half_w, (c.y * inv_w + 1.0f) * half_h, (c.z * inv_w) * 0.5f + 0.5f};
    };
    // Per vertex once: which planes it is beyond and (inside them all) its window position.
    auto clip = [&](uint32_t v) { return frame.mvp * glm::vec4(m.positions[v], 1.0f); };
    window_.resize(m.vertex_count());
    outside_.resize(m.vertex_count());
    parallel_for(m.vertex_count(), [&](size_t v) {
        const glm::vec4 c = clip(uint32_t(v));
        outside_[v] = uint8_t(outside(c));
        if (!outside_[v]) window_[v] = to_window(c);
    });
    // One polygon (window vertices, any winding) with the piece's culling, fanned into triangles.
    auto fill_polygon = [&](const WindowVertex* w, int n, const Piece& piece, float* target, glm::ivec4* drawn) {
        float area2 = 0;  // twice the signed area; > 0: counter-clockwise
        if (n == 3) area2 = (w[1].x - w[0].x) * (w[2].y - w[0].y) - (w[2].x - w[0].x) * (w[1].y - w[0].y);
        else
            for (int i = 0; i < n; ++i) area2 += w[i].x * w[(i + 1) % n].y - w[(i + 1) % n].x * w[i].y;  // shoelace
        if (!(area2 != 0.0f)) return;
        const bool front = (area2 > 0) != triangles.mirrored;
        if ((piece.cull == Cull::Back && !front) || (piece.cull == Cull::Front && front)) return;
        const Target t{target, width, piece.rect, drawn};
        for (int i = 1; i + 1 < n; ++i) {
            WindowVertex a = w[0], b = w[i], c = w[i + 1];
            float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
            if (area < 0) std::swap(b, c), area = -area;
            if (area > 0) fill(a, b, c, area, t);
        }
    };

    // Contiguous ranges of the pieces' faces, each into its own buffer.
    const size_t slots = std::max<size_t>(1, std::min<size_t>(max_slots, (faces + 4095) / 4096));
    parallel_for_dynamic(slots, [&](size_t s) {
        if (s > 0) clear(s);
        std::vector<float>& buffer = buffers_[s];
        glm::ivec4* drawn = &drawn_[s];
        const size_t begin = faces * s / slots, end = faces * (s + 1) / slots;
        size_t offset = 0;
        for (const Piece& piece : pieces) {
            const size_t lo = std::max(begin, offset), hi = std::min(end, offset + piece.count);
            for (size_t k = lo; k < hi; ++k) {
                const Face& f = m.faces[piece.first + (k - offset)];
                const unsigned o0 = outside_[f[0]], o1 = outside_[f[1]], o2 = outside_[f[2]];
                if (o0 & o1 & o2) continue;  // beyond one plane of the view volume
                if (!(o0 | o1 | o2)) {
                    const WindowVertex w[3] = {window_[f[0]], window_[f[1]], window_[f[2]]};
                    fill_polygon(w, 3, piece, buffer.data(), drawn);
                    continue;
                }
                const glm::vec4 c[3] = {clip(f[0]), clip(f[1]), clip(f[2])};  // the same bits as above
                glm::vec4 polygon[9];
                const int n = clip_polygon(c, polygon);
                WindowVertex w[9];
                for (int i = 0; i < n; ++i) w[i] = to_window(polygon[i]);
                if (n >= 3) fill_polygon(w, n, piece, buffer.data(), drawn);
            }
            offset += piece.count;
        }
    });
    // The nearest of the buffers, where the others drew.
    for (size_t s = 1; s < slots; ++s) {
        const glm::ivec4 r = drawn_[s];
        if (r.x >= r.z || r.y >= r.w) continue;
        const float* other = buffers_[s].data();
        parallel_for_ranges(size_t(r.w - r.y), [&](size_t begin, size_t end) {
            for (size_t y = size_t(r.y) + begin; y < size_t(r.y) + end; ++y)
                for (size_t i = y * size_t(width) + size_t(r.x); i < y * size_t(width) + size_t(r.z); ++i)
                    depth[i] = std::min(depth[i], other[i]);
        }, 64);
        glm::ivec4& d = drawn_[0];
        d = {std::min(d.x, r.x), std::min(d.y, r.y), std::max(d.z, r.z), std::max(d.w, r.w)};
    }
    return depth;
}

}  // namespace kappa::render
