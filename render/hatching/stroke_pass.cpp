#include "render/hatching/stroke_pass.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace kappa::render {

namespace {

struct StrokeVertex {
    glm::vec2 window;
    float width, alpha;
};

}  // namespace

float tapered_width(float width, float taper, float s, float total) {
    if (taper <= 0) return width;
    return width * std::min(1.0f, 0.2f + 0.8f * std::min(s, total - s) / taper);
}

StrokePass::StrokePass()
    : program_(geometry_stage_program(
          {{GL_VERTEX_SHADER, {"hatching/strokes_vert.glsl"}},
           {GL_GEOMETRY_SHADER, {"lines/segment_emit.glsl", "lines/line_quad.glsl", "hatching/strokes_geom.glsl"}},
           {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}})) {
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &buffer_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(StrokeVertex), reinterpret_cast<const void*>(0));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, sizeof(StrokeVertex),
                          reinterpret_cast<const void*>(offsetof(StrokeVertex, width)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(StrokeVertex),
                          reinterpret_cast<const void*>(offsetof(StrokeVertex, alpha)));
    glBindVertexArray(0);
}

StrokePass::~StrokePass() {
    glDeleteBuffers(1, &buffer_);
    glDeleteVertexArrays(1, &vao_);
}

std::vector<WindowSegment> stroke_window_segments(const std::vector<Stroke>& strokes, float default_width,
                                                  const FrameParams& frame) {
    std::vector<WindowSegment> out;
    const float height = frame.viewport.y;
    for (const Stroke& s : strokes) {
        float total = 0;
        for (size_t i = 0; i + 1 < s.points.size(); ++i) total += glm::distance(s.points[i], s.points[i + 1]);
        const float width = s.width > 0 ? s.width : default_width;
        float along = 0;
        for (size_t i = 0; i + 1 < s.points.size(); ++i) {
            const float len = glm::distance(s.points[i], s.points[i + 1]);
            WindowSegment seg;
            seg.a = {s.points[i].x, height - s.points[i].y, 0.0f};  // at the near plane: never hidden
            seg.b = {s.points[i + 1].x, height - s.points[i + 1].y, 0.0f};
            seg.alpha = {s.opacity[i], s.opacity[i + 1]};
            seg.on_surface = true;
            seg.width = tapered_width(width, s.taper, along + 0.5f * len, total);
            out.push_back(seg);
            along += len;
        }
    }
    return out;
}

void StrokePass::draw(const std::vector<WindowSegment>& segments, const FrameParams& frame,
                      unsigned surface_depth_texture) {
    if (segments.empty()) return;
    std::vector<StrokeVertex> ends;  // GL_LINES
    ends.reserve(2 * segments.size());
    for (const WindowSegment& seg : segments) {
        ends.push_back({glm::vec2(seg.a), seg.width, seg.alpha.x});
        ends.push_back({glm::vec2(seg.b), seg.width, seg.alpha.y});
    }
    program_.use();
    program_.set("u_viewport", frame.viewport);
    program_.set("u_depth", 0);
    program_.set("u_depth_params", glm::vec2(frame.projection[2][2], frame.projection[3][2]));
    program_.set("u_hidden_lines", 0);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MAX);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, surface_depth_texture);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(ends.size() * sizeof(StrokeVertex)), ends.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_LINES, 0, GLsizei(ends.size()));
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
}

}  // namespace kappa::render
