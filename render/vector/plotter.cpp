#include "render/vector/plotter.h"

#include "render/vector/stroke_cleanup.h"
#include "render/vector/vector_drawing.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace kappa::render {

namespace {

// Points of kept paths in cells of `radius` pixels, to find samples near them.
class PointGrid {
public:
    explicit PointGrid(float radius) : cell_(radius) {}
    void add(glm::vec2 p, size_t owner) { cells_[key(cell_of(p))].push_back({p, owner}); }
    bool near_other(glm::vec2 p, size_t owner) const {
        const glm::ivec2 c = cell_of(p);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const auto it = cells_.find(key(c + glm::ivec2(dx, dy)));
                if (it == cells_.end()) continue;
                for (const Entry& e : it->second)
                    if (e.owner != owner && glm::distance(e.p, p) <= cell_) return true;
            }
        return false;
    }

private:
    struct Entry {
        glm::vec2 p;
        size_t owner;
    };
    glm::ivec2 cell_of(glm::vec2 p) const { return glm::ivec2(glm::floor(p / cell_)); }
    static uint64_t key(glm::ivec2 c) { return uint64_t(uint32_t(c.x)) << 32 | uint32_t(c.y); }
    float cell_;
    std::unordered_map<uint64_t, std::vector<Entry>> cells_;
};

// The parts of a stroke at half ink or more, resampled every half pixel.
std::vector<Stroke> inked_parts(const Stroke& s) {
    std::vector<Stroke> parts;
    Stroke run;
    run.type = s.type;
    run.hidden = s.hidden;
    auto flush = [&] {
        if (run.points.size() >= 2) parts.push_back(run);
        run.points.clear(), run.opacity.clear();
    };
    for (size_t i = 0; i + 1 < s.points.size(); ++i) {
        const glm::vec2 a = s.points[i], b = s.points[i + 1];
        const int steps = std::max(1, int(std::ceil(2.0f * glm::distance(a, b))));
        for (int k = (i == 0 ? 0 : 1); k <= steps; ++k) {
            const float t = float(k) / float(steps);
            const float o = s.opacity[i] + (s.opacity[i + 1] - s.opacity[i]) * t;
            if (o >= 0.5f) run.points.push_back(a + (b - a) * t), run.opacity.push_back(1.0f);
            else flush();
        }
    }
    flush();
    return parts;
}

glm::vec2 start_of(const Stroke& s) { return s.points.front(); }
glm::vec2 end_of(const Stroke& s) { return s.points.back(); }

void reverse(Stroke& s) {
    std::reverse(s.points.begin(), s.points.end());
    std::reverse(s.opacity.begin(), s.opacity.end());
    std::reverse(s.strength.begin(), s.strength.end());
    std::reverse(s.surface.begin(), s.surface.end());
}

// Joins paths of one type whose ends are within radius: each path is grown
// at its end, then at its start, while another path's end is that near.
std::vector<Stroke> join_touching(std::vector<Stroke> strokes, float radius) {
    std::unordered_map<uint64_t, std::vector<size_t>> ends;  // cell -> paths with an end there
    auto cell = [&](glm::vec2 p) {
        const glm::ivec2 c(glm::floor(p / radius));
        return uint64_t(uint32_t(c.x)) << 32 | uint32_t(c.y);
    };
    for (size_t i = 0; i < strokes.size(); ++i)
        for (glm::vec2 p : {start_of(strokes[i]), end_of(strokes[i])}) ends[cell(p)].push_back(i);
    std::vector<char> alive(strokes.size(), 1);
    // Another live path of a's type with an end within radius of p; reversed so that it starts there.
    auto take_near = [&](size_t a, LineType type, bool hidden, glm::vec2 p, Stroke& out) {
        const glm::ivec2 c(glm::floor(p / radius));
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const glm::ivec2 n = c + glm::ivec2(dx, dy);
                const auto it = ends.find(uint64_t(uint32_t(n.x)) << 32 | uint32_t(n.y));
                if (it == ends.end()) continue;
                for (size_t b : it->second) {
                    if (b == a || !alive[b] || strokes[b].type != type || strokes[b].hidden != hidden) continue;
                    const bool at_start = glm::distance(start_of(strokes[b]), p) <= radius;
                    if (!at_start && glm::distance(end_of(strokes[b]), p) > radius) continue;
                    alive[b] = 0;
                    out = std::move(strokes[b]);
                    if (!at_start) reverse(out);
                    return true;
                }
            }
        return false;
    };
    std::vector<Stroke> out;
    for (size_t a = 0; a < strokes.size(); ++a) {
        if (!alive[a]) continue;
        alive[a] = 0;
        Stroke path = std::move(strokes[a]);
        for (int side = 0; side < 2; ++side) {
            Stroke next;
            while (take_near(a, path.type, path.hidden, end_of(path), next)) {
                path.points.insert(path.points.end(), next.points.begin(), next.points.end());
                path.opacity.insert(path.opacity.end(), next.opacity.begin(), next.opacity.end());
            }
            reverse(path);  // then grow the other end
        }
        out.push_back(std::move(path));
    }
    return out;
}

// Greedy nearest-end order within each line type, from `pen`.
std::vector<Stroke> greedy_order(std::vector<Stroke> strokes) {
    std::vector<Stroke> out;
    glm::vec2 pen(0);
    std::vector<char> done(strokes.size(), 0);
    for (size_t n = 0; n < strokes.size(); ++n) {
        // The next line type still to draw: the first layer left.
        int rank = kLineTypeCount;
        for (size_t i = 0; i < strokes.size(); ++i)
            if (!done[i]) rank = std::min(rank, layer_rank(strokes[i].type));
        size_t best = 0;
        bool best_reversed = false;
        float best_d = INFINITY;
        for (size_t i = 0; i < strokes.size(); ++i) {
            if (done[i] || layer_rank(strokes[i].type) != rank) continue;
            const float ds = glm::distance(pen, start_of(strokes[i])), de = glm::distance(pen, end_of(strokes[i]));
            if (ds < best_d) best_d = ds, best = i, best_reversed = false;
            if (de < best_d) best_d = de, best = i, best_reversed = true;
        }
        done[best] = 1;
        Stroke s = strokes[best];
        if (best_reversed) reverse(s);
        pen = end_of(s);
        out.push_back(std::move(s));
    }
    return out;
}

}  // namespace

double pen_up_travel(const std::vector<Stroke>& strokes) {
    double travel = 0;
    glm::vec2 pen(0);
    for (const Stroke& s : strokes) {
        if (s.points.empty()) continue;
        travel += glm::distance(pen, start_of(s));
        pen = end_of(s);
    }
    return travel;
}

std::vector<Stroke> plotter_paths(std::vector<Stroke> strokes, float radius) {
    // 1. Full ink where at least half.
    std::vector<Stroke> inked;
    for (const Stroke& s : strokes)
        for (Stroke& part : inked_parts(s)) inked.push_back(std::move(part));
    // 2. Overlaps: longest first (stable, so ties keep their order).
    std::vector<size_t> order(inked.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<float> length(inked.size());
    for (size_t i = 0; i < inked.size(); ++i) length[i] = stroke_length(inked[i]);
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return length[a] > length[b]; });
    PointGrid grid(radius);
    std::vector<Stroke> kept;
    for (size_t i : order) {
        const Stroke& s = inked[i];
        Stroke run;
        run.type = s.type;
        run.hidden = s.hidden;
        std::vector<Stroke> runs;
        for (size_t k = 0; k < s.points.size(); ++k) {
            if (grid.near_other(s.points[k], i)) {
                if (run.points.size() >= 2) runs.push_back(run);
                run.points.clear(), run.opacity.clear();
            } else {
                run.points.push_back(s.points[k]), run.opacity.push_back(1.0f);
            }
        }
        if (run.points.size() >= 2) runs.push_back(run);
        for (const Stroke& r : runs)
            for (const glm::vec2& p : r.points) grid.add(p, i);
        for (Stroke& r : runs) kept.push_back(std::move(r));
    }
    // 3. Joined where they meet, then simplified back from the half-pixel samples.
    kept = join_touching(std::move(kept), 2 * radius);  // step 2 leaves gaps of up to radius + half a pixel
    simplify_strokes(kept, 0.25f);
    // The files write one line type after another: the order to beat is that one.
    std::stable_sort(kept.begin(), kept.end(),
                     [](const Stroke& a, const Stroke& b) { return layer_rank(a.type) < layer_rank(b.type); });
    // 4. Ordered, unless the given order already travels less.
    std::vector<Stroke> ordered = greedy_order(kept);
    return pen_up_travel(ordered) <= pen_up_travel(kept) ? ordered : kept;
}

}  // namespace kappa::render
