#include "render/hatching/hatch_streamlines.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <deque>

namespace kappa::render {

namespace {

constexpr float kMaxSeparations = 8;   // no strokes where they would be farther apart (in spacings)
constexpr float kTestRatio = 0.6f;     // a streamline stops this close to another (in separations)
constexpr float kStep = 1.0f;          // pixels
constexpr float kFallbackWeight = 0.05f;

// The smoothed field and what tracing asks of it, in window pixels.
class Field {
public:
    // The averaged directions live on a grid of `cell` pixels (half a
    // spacing): the Gaussian is two spacings wide, so nothing finer survives it.
    Field(const HatchField& f, int family, float sigma, float cell)
        : f_(f), w_(f.width), h_(f.height), cell_(std::max(1.0f, cell)),
          gw_(int(std::ceil(float(w_) / cell_))), gh_(int(std::ceil(float(h_) / cell_))) {
        // Cell sums of the doubled-angle vectors over the surface (z: the surface pixels).
        std::vector<glm::vec3> src(size_t(gw_) * size_t(gh_), glm::vec3(0)), tmp(src.size());
        for (int y = 0; y < h_; ++y)
            for (int x = 0; x < w_; ++x) {
                const size_t i = size_t(y) * size_t(w_) + size_t(x);
                const glm::vec4& d = f.directions[i];
                if (f.tone[i].y > 0.5f)
                    src[grid_index(int(float(x) / cell_), int(float(y) / cell_))] +=
                        family == 0 ? glm::vec3(d.x, d.y, 1.0f) : glm::vec3(d.z, d.w, 1.0f);
            }
        // Normalised Gaussian averaging, separable, in cells.
        const float sc = sigma / cell_;
        const int r = std::max(1, int(std::ceil(2.5f * sc)));
        std::vector<float> k(size_t(2 * r + 1));
        for (int i = -r; i <= r; ++i) k[size_t(i + r)] = std::exp(-0.5f * float(i * i) / (sc * sc));
        for (int y = 0; y < gh_; ++y)
            for (int x = 0; x < gw_; ++x) {
                glm::vec3 sum(0);
                for (int i = std::max(-r, -x); i <= std::min(r, gw_ - 1 - x); ++i)
                    sum += k[size_t(i + r)] * src[grid_index(x + i, y)];
                tmp[grid_index(x, y)] = sum;
            }
        dir_.assign(src.size(), glm::vec2(0));
        for (int y = 0; y < gh_; ++y)
            for (int x = 0; x < gw_; ++x) {
                glm::vec3 sum(0);
                for (int i = std::max(-r, -y); i <= std::min(r, gh_ - 1 - y); ++i)
                    sum += k[size_t(i + r)] * tmp[grid_index(x, y + i)];
                // The mean of the weighted vectors, plus a little of the 45-degree fallback.
                const glm::vec2 mean = sum.z > 0 ? glm::vec2(sum) / sum.z : glm::vec2(0);
                dir_[grid_index(x, y)] = mean + kFallbackWeight * glm::vec2(0, 1);  // (cos 90, sin 90): 45 degrees
            }
    }

    bool inside(glm::vec2 p) const { return p.x >= 0 && p.y >= 0 && p.x < float(w_) && p.y < float(h_); }
    bool on_surface(glm::vec2 p) const { return inside(p) && tone(p).y > 0.5f && depth(p) < 1.0f; }
    float darkness(glm::vec2 p) const { return tone(p).x; }
    float distance(glm::vec2 p) const { return f_.p32 / (depth(p) * 2.0f - 1.0f + f_.p22); }
    // The unit direction at p (bilinear in the doubled angle), turned to agree with `along`.
    glm::vec2 direction(glm::vec2 p, glm::vec2 along) const {
        const glm::vec2 q = glm::clamp(p / cell_ - 0.5f, glm::vec2(0), glm::vec2(float(gw_ - 1), float(gh_ - 1)));
        const int x0 = int(q.x), y0 = int(q.y), x1 = std::min(x0 + 1, gw_ - 1), y1 = std::min(y0 + 1, gh_ - 1);
        const float fx = q.x - float(x0), fy = q.y - float(y0);
        const glm::vec2 v = (1 - fy) * ((1 - fx) * dir_[grid_index(x0, y0)] + fx * dir_[grid_index(x1, y0)]) +
                            fy * ((1 - fx) * dir_[grid_index(x0, y1)] + fx * dir_[grid_index(x1, y1)]);
        const float a = 0.5f * std::atan2(v.y, v.x);
        const glm::vec2 d(std::cos(a), std::sin(a));
        return glm::dot(d, along) < 0 ? -d : d;
    }

private:
    size_t grid_index(int x, int y) const { return size_t(y) * size_t(gw_) + size_t(x); }
    const glm::vec2& tone(glm::vec2 p) const { return f_.tone[size_t(int(p.y)) * size_t(w_) + size_t(int(p.x))]; }
    float depth(glm::vec2 p) const { return f_.depth[size_t(int(p.y)) * size_t(w_) + size_t(int(p.x))]; }
    const HatchField& f_;
    int w_, h_;
    float cell_;
    int gw_, gh_;
    std::vector<glm::vec2> dir_;  // averaged doubled-angle vectors per cell
};

// Points of the streamlines drawn so far, in cells of one spacing.
class PointGrid {
public:
    PointGrid(int width, int height, float cell)
        : cell_(cell), nx_(int(std::ceil(float(width) / cell)) + 1), ny_(int(std::ceil(float(height) / cell)) + 1),
          cells_(size_t(nx_) * size_t(ny_)) {}
    void add(glm::vec2 p, int line) { cells_[cell_index(p)].push_back({p, line}); }
    // Whether a point of another streamline (or of `line` itself, before its point `own_before`) is within r.
    bool occupied(glm::vec2 p, float r, int line, size_t own_count, size_t own_recent) const {
        const int cx = int(p.x / cell_), cy = int(p.y / cell_), reach = int(std::ceil(r / cell_));
        for (int y = std::max(0, cy - reach); y <= std::min(ny_ - 1, cy + reach); ++y)
            for (int x = std::max(0, cx - reach); x <= std::min(nx_ - 1, cx + reach); ++x)
                for (const Entry& e : cells_[size_t(y) * size_t(nx_) + size_t(x)])
                    if (glm::distance(e.p, p) < r && (e.line != line || e.order + own_recent < own_count)) return true;
        return false;
    }
    void add_own(glm::vec2 p, int line, size_t order) { cells_[cell_index(p)].push_back({p, line, order}); }

private:
    struct Entry {
        glm::vec2 p;
        int line;
        size_t order = 0;
    };
    size_t cell_index(glm::vec2 p) const {
        const int x = std::clamp(int(p.x / cell_), 0, nx_ - 1), y = std::clamp(int(p.y / cell_), 0, ny_ - 1);
        return size_t(y) * size_t(nx_) + size_t(x);
    }
    float cell_;
    int nx_, ny_;
    std::vector<std::vector<Entry>> cells_;
};

}  // namespace

std::vector<Stroke> trace_hatching(const HatchField& hatch, const std::vector<glm::vec2>& seeds,
                                   const HatchParams& params) {
    std::vector<Stroke> strokes;
    if (hatch.width <= 0 || hatch.height <= 0 || params.spacing <= 0) return strokes;
    const Field field(hatch, params.family, 2.0f * params.spacing, 0.5f * params.spacing);
    PointGrid grid(hatch.width, hatch.height, params.spacing);
    // Separation of strokes at p (pixels), or 0 where the tone wants none.
    auto separation = [&](glm::vec2 p) {
        float t = field.darkness(p);
        if (params.cross_family) t = (t - 0.4f) / 0.6f;
        const float d = t > 0 ? params.spacing / t : INFINITY;
        return d <= kMaxSeparations * params.spacing ? d : 0.0f;
    };
    int line_id = 0;
    std::deque<glm::vec2> candidates;
    auto valid_seed = [&](glm::vec2 p) {
        if (!field.on_surface(p)) return false;
        const float d = separation(p);
        return d > 0 && !grid.occupied(p, d, -1, 0, 0);
    };
    // Traces one way from the seed; returns the points after the seed.
    auto trace = [&](glm::vec2 seed, glm::vec2 start_dir, size_t already) {
        std::vector<glm::vec2> points;
        glm::vec2 p = seed, along = start_dir;
        float length = 0, last_distance = field.distance(seed);
        const size_t own_recent = size_t(std::ceil(kMaxSeparations * params.spacing / kStep)) + 2;
        while (length < 0.5f * params.max_length) {
            const glm::vec2 d0 = field.direction(p, along);
            const glm::vec2 mid = p + 0.5f * kStep * d0;
            if (!field.on_surface(mid)) break;
            const glm::vec2 d1 = field.direction(mid, d0);
            const glm::vec2 next = p + kStep * d1;
            if (!field.on_surface(next)) break;
            const float dist = field.distance(next);
            if (std::fabs(dist - last_distance) > 0.02f * dist) break;  // an occluding edge
            const float sep = separation(next);
            if (sep <= 0) break;
            if (grid.occupied(next, kTestRatio * sep, line_id, already + points.size(), own_recent)) break;
            points.push_back(next);
            p = next, along = d1, last_distance = dist, length += kStep;
        }
        return points;
    };
    auto try_seed = [&](glm::vec2 seed) {
        if (!valid_seed(seed)) return;
        const glm::vec2 d = field.direction(seed, glm::vec2(1, 0));
        std::vector<glm::vec2> forward = trace(seed, d, 0);
        std::vector<glm::vec2> backward = trace(seed, -d, forward.size());
        std::vector<glm::vec2> line(backward.rbegin(), backward.rend());
        line.push_back(seed);
        line.insert(line.end(), forward.begin(), forward.end());
        if (float(line.size() - 1) * kStep < 2.0f * params.spacing) return;
        for (size_t i = 0; i < line.size(); ++i) grid.add_own(line[i], line_id, i);
        // Candidate seeds one separation to either side (Jobard and Lefer).
        for (size_t i = 0; i < line.size(); i += size_t(std::max(1.0f, params.spacing))) {
            const glm::vec2 t = i + 1 < line.size() ? glm::normalize(line[i + 1] - line[i]) : glm::normalize(line[i] - line[i - 1]);
            const glm::vec2 n(-t.y, t.x);
            const float sep = separation(line[i]);
            if (sep <= 0) continue;
            candidates.push_back(line[i] + sep * n);
            candidates.push_back(line[i] - sep * n);
        }
        Stroke s;
        s.type = LineType::Hatching;
        s.taper = params.taper;
        for (const glm::vec2& p : line) s.points.push_back({p.x, float(hatch.height) - p.y}), s.opacity.push_back(1.0f);
        strokes.push_back(std::move(s));
        ++line_id;
    };
    for (const glm::vec2& seed : seeds) {
        try_seed(seed);
        while (!candidates.empty()) {
            const glm::vec2 c = candidates.front();
            candidates.pop_front();
            try_seed(c);
        }
    }
    return strokes;
}

}  // namespace kappa::render
