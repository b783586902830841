#include "render/cpu_isolines.h"

#include "geometry/lines/line_extraction.h"
#include "geometry/lines/view_quantities.h"
#include "geometry/parallel.h"
#include "render/cluster_culling.h"

#include <algorithm>
#include <cstddef>

namespace kappa::render {

namespace {

struct SegmentVertex {
    glm::vec3 position;
    float alpha, tolerance, contour;
};

}  // namespace

CpuIsolinePass::CpuIsolinePass()
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

CpuIsolinePass::~CpuIsolinePass() {
    glDeleteBuffers(1, &buffer_);
    glDeleteVertexArrays(1, &vao_);
}

void CpuIsolinePass::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s) {
    const LineSelection& l = s.lines;
    const bool contours = l.any_contours(), highlights = l.suggestive_highlights;
    if (!(contours || l.suggestive || highlights || l.dwkr)) return;
    LineExtractionOptions o;
    o.contours = contours, o.suggestive = l.suggestive, o.suggestive_highlights = highlights, o.dwkr = l.dwkr;
    o.boundaries = o.creases = false;
    o.sc_threshold = s.sc_threshold, o.sh_threshold = s.sh_threshold, o.fade = s.fade;
    const Mesh& m = mesh.cpu_mesh();
    const ViewQuantities q =
        compute_view_quantities(m, mesh.cpu_fields(), mesh.cpu_fine_normals(), frame.eye, mesh.feature_size());
    // The triangles that can hold a line, as the GPU pass draws them (same culling, same test).
    std::vector<FaceRun> runs =
        s.cull_clusters && !l.dwkr
            ? contour_pass_runs(mesh.clusters(), frame, contours, l.suggestive || highlights,
                                highlights ? -1e30f : s.sc_threshold, 0.5f * s.line_width + 2.0f)
            : std::vector<FaceRun>{{0, uint32_t(m.face_count())}};
    // Runs cut into pieces of at most 4096 faces, extracted in parallel, joined in order.
    std::vector<FaceRun> pieces;
    for (const FaceRun& r : runs)
        for (uint32_t first = r.first; first < r.first + r.count; first += 4096)
            pieces.push_back({first, std::min<uint32_t>(4096, r.first + r.count - first)});
    std::vector<ExtractedLines> found(pieces.size());
    parallel_for(pieces.size(), [&](size_t i) {
        for (uint32_t f = pieces[i].first; f < pieces[i].first + pieces[i].count; ++f)
            extract_view_lines_of_face(m, m.faces[f], mesh.cpu_fields(), q, o, found[i]);
    }, 1);
    std::vector<SegmentVertex> vertices;
    for (const ExtractedLines& lines : found)
        for (int type = 0; type < kLineTypeCount; ++type)
            for (const LineSegment& seg : lines[size_t(type)]) {
                const float contour = type == int(LineType::Contour) ? 1.0f : 0.0f;
                vertices.push_back({seg.a, seg.opacity_a, seg.tolerance, contour});
                vertices.push_back({seg.b, seg.opacity_b, seg.tolerance, contour});
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
