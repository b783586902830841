#include "level_lines.h"

#include "geometry/lines/zero_crossings.h"
#include "geometry/parallel/parallel.h"

#include <algorithm>
#include <cmath>

namespace kappa {

using namespace lines;

namespace {

void levels_of_face(const Mesh& mesh, const Face& t, const std::vector<float>& value, const LevelSet& levels,
                    std::vector<LineSegment>& out) {
    const float first = levels.first, step = levels.step;
    const int count = levels.count;
    if (count <= 0 || !(step > 0)) return;
    const glm::vec3 p[3] = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
    const float v[3] = {value[t[0]], value[t[1]], value[t[2]]};
    const float lo = std::min({v[0], v[1], v[2]}), hi = std::max({v[0], v[1], v[2]});
    const int k0 = std::max(0, int(std::ceil((lo - first) / step)));
    const int k1 = std::min(count - 1, int(std::floor((hi - first) / step)));
    for (int k = k0; k <= k1; ++k) {
        const float level = first + float(k) * step;
        const float f[3] = {v[0] - level, v[1] - level, v[2] - level};
        Crossing c0, c1;
        if (find_crossings(t, f, c0, c1))
            out.push_back({point_at(c0, p), point_at(c1, p), 1, 1, level, level, half_longest_edge(p)});
    }
}

}  // namespace

LevelSet isophote_level_set(int count) {
    const float step = 1.0f / float(std::max(1, count));
    return {0.5f * step, step, count};
}

LevelSet topo_level_set(float center_y, float radius, int count) {
    const float step = 2.0f * radius / float(std::max(1, count));
    return {center_y - radius + 0.5f * step, step, count};
}

LevelValues level_values(const Mesh& mesh, const SurfaceFields& fields, const LineExtractionOptions& o) {
    LevelValues v;
    begin_level_values(mesh.vertex_count(), o, v);
    parallel_for_ranges(mesh.vertex_count(),
                        [&](size_t begin, size_t end) { level_values(mesh, fields, o, begin, end, v); });
    return v;
}

void begin_level_values(size_t n, const LineExtractionOptions& o, LevelValues& v) {
    v.isophote.resize(o.isophotes && o.isophote_levels.count > 0 ? n : 0);
    v.height.resize(o.topo && o.topo_levels.count > 0 ? n : 0);
}

void level_values(const Mesh& mesh, const SurfaceFields& fields, const LineExtractionOptions& o, size_t begin,
                  size_t end, LevelValues& v) {
    if (!v.isophote.empty())
        for (size_t i = begin; i < end; ++i) v.isophote[i] = glm::dot(fields.normals[i], o.light);
    if (!v.height.empty())
        for (size_t i = begin; i < end; ++i) v.height[i] = mesh.positions[i].y;
}

void level_lines_of_face(const Mesh& mesh, const Face& t, const LevelValues& v, const LineExtractionOptions& o,
                         ExtractedLines& lines) {
    if (o.isophotes && !v.isophote.empty())
        levels_of_face(mesh, t, v.isophote, o.isophote_levels, lines[int(LineType::Isophote)]);
    if (o.topo && !v.height.empty()) levels_of_face(mesh, t, v.height, o.topo_levels, lines[int(LineType::Topo)]);
}

void extract_level_lines(const Mesh& mesh, const SurfaceFields& fields, const LineExtractionOptions& o,
                         ExtractedLines& lines) {
    if (!(o.isophotes || o.topo)) return;
    const LevelValues v = level_values(mesh, fields, o);
    for (const Face& t : mesh.faces) level_lines_of_face(mesh, t, v, o, lines);
}

}  // namespace kappa
