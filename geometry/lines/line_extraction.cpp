#include "line_extraction.h"

#include "geometry/mesh/creases.h"
#include "geometry/lines/curvature_lines.h"
#include "geometry/lines/level_lines.h"
#include "geometry/lines/view_ridges.h"
#include "geometry/lines/zero_crossings.h"
#include "geometry/surface_fields.h"
#include "geometry/curvature/vertex_flags.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace kappa {

namespace {

using namespace lines;

void contour_segment(const Face& t, const glm::vec3 p[3], const ViewQuantities& q, std::vector<LineSegment>& out) {
    const float f[3] = {q.contour_ndotv[t[0]], q.contour_ndotv[t[1]], q.contour_ndotv[t[2]]};
    Crossing c0, c1;
    if (!find_crossings(t, f, c0, c1)) return;
    out.push_back({point_at(c0, p), point_at(c1, p), 1, 1, 1, 1, half_longest_edge(p)});
}

// The zero set of kr kept where sign * Dw kr fs^2 - threshold > 0 and n.v > 0
// (sign 1: suggestive contours, -1: suggestive highlights), faded over
// [threshold, threshold + max(threshold, 0.05)] as the shaders.
void suggestive_segment(const Face& t, const glm::vec3 p[3], const SurfaceFields& fields, const ViewQuantities& q,
                        float sign, float threshold, bool fade, std::vector<LineSegment>& out) {
    if (fields.unreliable(t[0]) || fields.unreliable(t[1]) || fields.unreliable(t[2])) return;
    const float f[3] = {q.kr[t[0]], q.kr[t[1]], q.kr[t[2]]};
    Crossing x0, x1;
    if (!find_crossings(t, f, x0, x1)) return;
    const float strength[3] = {q.sc_strength[t[0]], q.sc_strength[t[1]], q.sc_strength[t[2]]};
    const float ndotv[3] = {q.ndotv[t[0]], q.ndotv[t[1]], q.ndotv[t[2]]};
    const float g0 = sign * lerp_at(x0, strength) - threshold, g1 = sign * lerp_at(x1, strength) - threshold;
    glm::vec2 range(0, 1);
    if (!clip_positive(g0, g1, range)) return;
    if (!clip_positive(lerp_at(x0, ndotv), lerp_at(x1, ndotv), range)) return;
    float a0 = 1, a1 = 1;
    if (fade) {
        const float ramp = std::max(threshold, 0.05f);
        a0 = std::clamp((g0 + (g1 - g0) * range.x) / ramp, 0.0f, 1.0f);
        a1 = std::clamp((g0 + (g1 - g0) * range.y) / ramp, 0.0f, 1.0f);
    }
    if (std::max(a0, a1) <= 0.0f) return;
    const glm::vec3 c0 = point_at(x0, p), c1 = point_at(x1, p);
    const float s0 = lerp_at(x0, strength), s1 = lerp_at(x1, strength);  // Dw kr fs^2 at the two crossings
    out.push_back({c0 + (c1 - c0) * range.x, c0 + (c1 - c0) * range.y, a0, a1, s0 + (s1 - s0) * range.x,
                   s0 + (s1 - s0) * range.y, half_longest_edge(p)});
}

// Dw kr fs^2 = s on the front-facing side, not faded (as rtsc).
void dwkr_segment(const Face& t, const glm::vec3 p[3], const SurfaceFields& fields, const ViewQuantities& q,
                  float s, std::vector<LineSegment>& out) {
    if (fields.unreliable(t[0]) || fields.unreliable(t[1]) || fields.unreliable(t[2])) return;
    const float f[3] = {q.sc_strength[t[0]] - s, q.sc_strength[t[1]] - s, q.sc_strength[t[2]] - s};
    Crossing x0, x1;
    if (!find_crossings(t, f, x0, x1)) return;
    const float ndotv[3] = {q.ndotv[t[0]], q.ndotv[t[1]], q.ndotv[t[2]]};
    glm::vec2 range(0, 1);
    if (!clip_positive(lerp_at(x0, ndotv), lerp_at(x1, ndotv), range)) return;
    const glm::vec3 c0 = point_at(x0, p), c1 = point_at(x1, p);
    out.push_back({c0 + (c1 - c0) * range.x, c0 + (c1 - c0) * range.y, 1, 1, s, s, half_longest_edge(p)});
}

}  // namespace

const char* line_type_name(LineType type) {
    switch (type) {
    case LineType::Contour: return "contours";
    case LineType::Suggestive: return "suggestive";
    case LineType::Boundary: return "boundaries";
    case LineType::Crease: return "creases";
    case LineType::SuggestiveHighlight: return "suggestive-highlights";
    case LineType::Dwkr: return "dwkr";
    case LineType::Ridge: return "ridges";
    case LineType::Valley: return "valleys";
    case LineType::Parabolic: return "parabolic";
    case LineType::MeanZero: return "mean-zero";
    case LineType::Isophote: return "isophotes";
    case LineType::Topo: return "topo";
    case LineType::ApparentRidge: return "apparent-ridges";
    case LineType::PrincipalHighlight: return "principal-highlights";
    case LineType::Hatching: return "hatching";
    }
    return "";
}

void extract_view_lines_of_face(const Mesh& mesh, const Face& t, const SurfaceFields& fields, const ViewQuantities& q,
                                const LineExtractionOptions& o, ExtractedLines& lines) {
    const glm::vec3 p[3] = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
    if (o.contours) contour_segment(t, p, q, lines[int(LineType::Contour)]);
    if (o.suggestive)
        suggestive_segment(t, p, fields, q, 1.0f, o.sc_threshold, o.fade, lines[int(LineType::Suggestive)]);
    if (o.suggestive_highlights)
        suggestive_segment(t, p, fields, q, -1.0f, o.sh_threshold, o.fade, lines[int(LineType::SuggestiveHighlight)]);
    if (o.dwkr) dwkr_segment(t, p, fields, q, o.sc_threshold, lines[int(LineType::Dwkr)]);
}

std::vector<CreaseEdge> crease_edges(const Mesh& mesh, const std::vector<glm::uvec2>& creases,
                                     const std::vector<glm::uvec2>& crease_faces) {
    std::vector<CreaseEdge> out;
    out.reserve(creases.size());
    for (size_t e = 0; e < creases.size(); ++e)
        out.push_back({mesh.positions[creases[e].x], mesh.positions[creases[e].y],
                       face_normal(mesh, mesh.faces[crease_faces[e].x]), face_normal(mesh, mesh.faces[crease_faces[e].y])});
    return out;
}

std::vector<glm::uvec2> boundary_edges(const Mesh& mesh, const std::vector<uint8_t>& flags) {
    const bool use_flags = flags.size() == mesh.positions.size();
    if (use_flags && std::none_of(flags.begin(), flags.end(), [](uint8_t f) { return f & kFlagBoundary; }))
        return {};
    auto on_boundary = [&](uint32_t v) { return !use_flags || (flags[v] & kFlagBoundary); };
    std::vector<uint64_t> keys;
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = f[k], b = f[(k + 1) % 3];
            if (!on_boundary(a) || !on_boundary(b)) continue;
            keys.push_back(uint64_t(std::min(a, b)) << 32 | std::max(a, b));
        }
    std::sort(keys.begin(), keys.end());
    std::vector<glm::uvec2> out;
    for (size_t i = 0; i < keys.size();) {
        size_t j = i;
        while (j < keys.size() && keys[j] == keys[i]) ++j;
        if (j - i == 1) out.push_back({uint32_t(keys[i] >> 32), uint32_t(keys[i])});
        i = j;
    }
    return out;
}

bool faces_eye(const Mesh& mesh, const SurfaceFields& fields, const Face& t, glm::vec3 eye) {
    for (int k = 0; k < 3; ++k)
        if (glm::dot(fields.normals[t[k]], eye - mesh.positions[t[k]]) > 0) return true;
    return false;
}

void append_boundary_segments(const Mesh& mesh, const std::vector<glm::uvec2>& edges, std::vector<LineSegment>& out) {
    for (const glm::uvec2& e : edges) {
        const glm::vec3 a = mesh.positions[e.x], b = mesh.positions[e.y];
        out.push_back({a, b, 1, 1, 1, 1, 0.5f * glm::distance(a, b)});
    }
}

void append_crease_segments(const std::vector<CreaseEdge>& creases, glm::vec3 eye, const LineExtractionOptions& o,
                            ExtractedLines& lines) {
    if (!o.creases && !o.contours) return;
    for (const CreaseEdge& c : creases) {
        const glm::vec3 a = c.a, b = c.b, na = c.normal_a, nb = c.normal_b;
        // As crease_geom.glsl: a face is turned towards the eye when it is at either end.
        const bool front_a = glm::dot(na, eye - a) > 0 || glm::dot(na, eye - b) > 0;
        const bool front_b = glm::dot(nb, eye - a) > 0 || glm::dot(nb, eye - b) > 0;
        const LineSegment s{a, b, 1, 1, 1, 1, 0.5f * glm::distance(a, b)};
        if (o.creases && (front_a || front_b || o.hidden_creases)) lines[int(LineType::Crease)].push_back(s);
        else if (o.contours && front_a != front_b) lines[int(LineType::Contour)].push_back(s);
    }
}

ExtractedLines extract_lines(const Mesh& mesh, const SurfaceFields& fields, const ViewQuantities& q, glm::vec3 eye,
                             const std::vector<CreaseEdge>& creases, const LineExtractionOptions& o) {
    ExtractedLines lines;
    const bool view_lines = o.contours || o.suggestive || o.suggestive_highlights || o.dwkr;
    const bool curvature_lines = o.parabolic || o.mean_zero || o.ridges || o.valleys;
    const LevelValues levels = level_values(mesh, fields, o);
    ViewRidgeOptions vr;
    vr.apparent_ridges = o.apparent_ridges, vr.principal_highlights = o.principal_highlights;
    vr.ar_threshold = o.ar_threshold, vr.ph_threshold = o.ph_threshold;
    vr.feature_size = o.feature_size, vr.fade = o.fade;
    const bool view_ridges = vr.apparent_ridges || vr.principal_highlights;
    const std::vector<ViewRidgeVertex> ridge_vertices =
        view_ridges ? view_ridge_vertices(mesh, fields, eye, o.feature_size) : std::vector<ViewRidgeVertex>{};
    for (const Face& t : mesh.faces) {
        if (view_lines) extract_view_lines_of_face(mesh, t, fields, q, o, lines);
        if (o.cull_back_faces && !faces_eye(mesh, fields, t, eye)) continue;
        if (curvature_lines) curvature_lines_of_face(mesh, t, fields, o, lines);
        if (o.isophotes || o.topo) level_lines_of_face(mesh, t, levels, o, lines);
        if (view_ridges)
            view_ridges_of_face(mesh, t, fields, ridge_vertices, vr, lines[int(LineType::ApparentRidge)],
                                lines[int(LineType::PrincipalHighlight)]);
    }
    if (o.boundaries) append_boundary_segments(mesh, boundary_edges(mesh, fields.flags), lines[int(LineType::Boundary)]);
    append_crease_segments(creases, eye, o, lines);
    return lines;
}

}  // namespace kappa
