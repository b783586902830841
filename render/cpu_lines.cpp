#include "render/cpu_lines.h"

#include "geometry/lines/curvature_lines.h"
#include "geometry/lines/level_lines.h"
#include "geometry/lines/line_extraction.h"
#include "geometry/lines/view_quantities.h"
#include "geometry/lines/view_ridges.h"
#include "geometry/parallel.h"
#include "render/cluster_culling.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cstddef>
#include <functional>

namespace kappa::render {

namespace {

struct SegmentVertex {
    glm::vec3 position;
    float alpha, tolerance, kind;  // kind: shaders/segments_vert.glsl
};

// Calls per_face(face, lines) for every face of the runs, in parallel over
// pieces of at most 4096 faces, and appends what they found to `out` in
// face order (the same for any thread count).
void extract_over(const std::vector<FaceRun>& runs, const std::function<void(uint32_t, ExtractedLines&)>& per_face,
                  std::vector<ExtractedLines>& out) {
    std::vector<FaceRun> pieces;
    for (const FaceRun& r : runs)
        for (uint32_t first = r.first; first < r.first + r.count; first += 4096)
            pieces.push_back({first, std::min<uint32_t>(4096, r.first + r.count - first)});
    const size_t base = out.size();
    out.resize(base + pieces.size());
    parallel_for(pieces.size(), [&](size_t i) {
        for (uint32_t f = pieces[i].first; f < pieces[i].first + pieces[i].count; ++f) per_face(f, out[base + i]);
    }, 1);
}

}  // namespace

CpuLinePass::CpuLinePass()
    : program_({{GL_VERTEX_SHADER, {"segments_vert.glsl"}},
                {GL_GEOMETRY_SHADER, {"line_quad.glsl", "segments_geom.glsl"}},
                {GL_FRAGMENT_SHADER, {"lines_frag.glsl"}}}) {
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &buffer_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    const GLsizei stride = sizeof(SegmentVertex);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(0));
    for (GLuint i = 1; i <= 3; ++i) {
        glEnableVertexAttribArray(i);
        glVertexAttribPointer(i, 1, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(offsetof(SegmentVertex, alpha) + (i - 1) * sizeof(float)));
    }
    glBindVertexArray(0);
}

CpuLinePass::~CpuLinePass() {
    glDeleteBuffers(1, &buffer_);
    glDeleteVertexArrays(1, &vao_);
}

void CpuLinePass::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s) {
    const LineSelection& l = s.lines;
    const Mesh& m = mesh.cpu_mesh();
    const SurfaceFields& fields = mesh.cpu_fields();
    const float fs = mesh.feature_size();
    const float margin = 0.5f * s.line_width + 2.0f;  // pixels a line may reach beyond its centre
    const std::vector<FaceRun> all{{0, uint32_t(m.face_count())}};
    auto runs_or_all = [&](auto runs) { return s.cull_clusters ? runs() : all; };
    LineExtractionOptions o;
    o.contours = l.any_contours(), o.suggestive = l.suggestive, o.suggestive_highlights = l.suggestive_highlights;
    o.dwkr = l.dwkr, o.ridges = l.ridges, o.valleys = l.valleys, o.parabolic = l.parabolic, o.mean_zero = l.mean_zero;
    o.isophotes = l.isophotes && s.isophote_count > 0, o.topo = l.topo && s.topo_count > 0;
    o.sc_threshold = s.sc_threshold, o.sh_threshold = s.sh_threshold, o.rv_threshold = s.rv_threshold;
    o.feature_size = fs, o.fade = s.fade;
    std::vector<ExtractedLines> found;

    // Contours, suggestive contours and highlights, Dw kr lines (the GPU contour pass's culling and tests).
    const bool highlights = l.suggestive_highlights;
    if (o.contours || o.suggestive || highlights || o.dwkr) {
        const ViewQuantities q = compute_view_quantities(m, fields, mesh.cpu_fine_normals(), frame.eye, fs);
        extract_over(runs_or_all([&] {
                         return contour_pass_runs(mesh.clusters(), frame, o.contours, o.suggestive || highlights,
                                                  highlights ? -1e30f : s.sc_threshold, margin, o.dwkr);
                     }),
                     [&](uint32_t f, ExtractedLines& out) { extract_view_lines_of_face(m, m.faces[f], fields, q, o, out); },
                     found);
    }
    if (l.curvature_lines())
        extract_over(runs_or_all([&] {
                         return curvature_line_runs(mesh.clusters(), frame, s.hidden_lines, margin, l, s.rv_threshold);
                     }),
                     [&](uint32_t f, ExtractedLines& out) { curvature_lines_of_face(m, m.faces[f], fields, o, out); },
                     found);
    if (l.view_ridges()) {
        ViewRidgeOptions vr;
        vr.apparent_ridges = l.apparent_ridges, vr.principal_highlights = l.principal_highlights;
        vr.ar_threshold = s.ar_threshold, vr.ph_threshold = s.ph_threshold, vr.feature_size = fs, vr.fade = s.fade;
        const std::vector<ViewRidgeVertex> vertices = view_ridge_vertices(m, fields, frame.eye, fs);
        extract_over(runs_or_all([&] {
                         return view_ridge_runs(mesh.clusters(), frame, s.hidden_lines, margin, l, s.ph_threshold);
                     }),
                     [&](uint32_t f, ExtractedLines& out) {
                         view_ridges_of_face(m, m.faces[f], fields, vertices, vr, out[int(LineType::ApparentRidge)],
                                             out[int(LineType::PrincipalHighlight)]);
                     },
                     found);
    }
    // Isophotes (the light as the shading's, in model coordinates) and topographic lines.
    if (o.isophotes) {
        LineExtractionOptions iso = o;
        iso.topo = false;
        iso.light = glm::normalize(glm::transpose(frame.normal_matrix) * camera_light_direction(s, frame));
        iso.isophote_count = s.isophote_count;
        const LevelValues values = level_values(m, fields, iso);
        const float step = 1.0f / float(s.isophote_count);
        extract_over(runs_or_all([&] {
                         return isophote_runs(mesh.clusters(), frame, s.hidden_lines, margin, iso.light,
                                              {0.5f * step, step, s.isophote_count});
                     }),
                     [&](uint32_t f, ExtractedLines& out) { level_lines_of_face(m, m.faces[f], values, iso, out); },
                     found);
    }
    if (o.topo) {
        LineExtractionOptions topo = o;
        topo.isophotes = false;
        topo.topo_count = s.topo_count;
        topo.topo_step = 2.0f * mesh.bounds().radius / float(s.topo_count);
        topo.topo_first = mesh.bounds().center.y - mesh.bounds().radius + 0.5f * topo.topo_step;
        const LevelValues values = level_values(m, fields, topo);
        extract_over(runs_or_all([&] {
                         return topo_runs(mesh.clusters(), frame, s.hidden_lines, margin,
                                          {topo.topo_first, topo.topo_step, topo.topo_count});
                     }),
                     [&](uint32_t f, ExtractedLines& out) { level_lines_of_face(m, m.faces[f], values, topo, out); },
                     found);
    }

    std::vector<SegmentVertex> vertices;
    for (const ExtractedLines& lines : found)
        for (int type = 0; type < kLineTypeCount; ++type)
            for (const LineSegment& seg : lines[size_t(type)]) {
                const bool isoline = is_view_isoline(LineType(type));
                const float kind = type == int(LineType::Contour) ? 2.0f : isoline ? 1.0f : 0.0f;
                vertices.push_back({seg.a, seg.opacity_a, seg.tolerance, kind});
                vertices.push_back({seg.b, seg.opacity_b, seg.tolerance, kind});
            }
    if (vertices.empty()) return;
    program_.use();
    program_.set("u_mvp", frame.mvp);
    program_.set("u_viewport", frame.viewport);
    program_.set("u_line_width", s.line_width);
    program_.set("u_depth", 0);
    program_.set("u_depth_params", glm::vec2(frame.projection[2][2], frame.projection[3][2]));
    program_.set("u_hidden_lines", int(s.hidden_lines));
    program_.set("u_scale_tolerance", s.detail * 2.0f / (frame.projection[1][1] * frame.viewport.y));
    program_.set("u_silhouette_only", int(l.silhouette && !l.contours));
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(SegmentVertex)), vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_LINES, 0, GLsizei(vertices.size()));
    glBindVertexArray(0);
}

}  // namespace kappa::render
