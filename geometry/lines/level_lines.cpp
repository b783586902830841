#include "level_lines.h"

#include "geometry/lines/zero_crossings.h"

#include <cmath>

namespace kappa {

using namespace lines;

namespace {

void levels(const Mesh& mesh, const std::vector<float>& value, float first, float step, int count,
            std::vector<LineSegment>& out) {
    if (count <= 0 || !(step > 0)) return;
    for (const Face& t : mesh.faces) {
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
}

}  // namespace

void extract_level_lines(const Mesh& mesh, const SurfaceFields& fields, const LineExtractionOptions& o,
                         ExtractedLines& lines) {
    std::vector<float> value(mesh.vertex_count());
    if (o.isophotes && o.isophote_count > 0) {
        for (size_t i = 0; i < value.size(); ++i) value[i] = glm::dot(fields.normals[i], o.light);
        const float step = 1.0f / float(o.isophote_count);
        levels(mesh, value, 0.5f * step, step, o.isophote_count, lines[int(LineType::Isophote)]);
    }
    if (o.topo && o.topo_count > 0) {
        for (size_t i = 0; i < value.size(); ++i) value[i] = mesh.positions[i].y;
        levels(mesh, value, o.topo_first, o.topo_step, o.topo_count, lines[int(LineType::Topo)]);
    }
}

}  // namespace kappa
