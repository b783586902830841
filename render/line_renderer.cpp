#include "render/line_renderer.h"

#include <glm/geometric.hpp>

#include <string>
#include <utility>
#include <vector>

namespace kappa::render {

namespace {

std::vector<ShaderStage> line_program(std::vector<std::string> geometry_files, std::string defines = {}) {
    return {{GL_VERTEX_SHADER, {"mesh_attributes.glsl", "view_dependent.glsl", "lines_vert.glsl"}},
            {GL_GEOMETRY_SHADER, std::move(geometry_files), std::move(defines)},
            {GL_FRAGMENT_SHADER, {"lines_frag.glsl"}}};
}

}  // namespace

LineRenderer::LineRenderer()
    : isolines_(line_program({"line_quad.glsl", "isolines_geom.glsl", "hatch_strokes.glsl"})),
      isolines_hatching_(
          line_program({"line_quad.glsl", "isolines_geom.glsl", "hatch_strokes.glsl"}, "#define KAPPA_HATCHING\n")),
      boundaries_(line_program({"line_quad.glsl", "boundary_geom.glsl"})) {}

void LineRenderer::set_common(ShaderProgram& p, const MeshBuffers& mesh, const FrameParams& frame,
                              const RenderSettings& s) {
    p.use();
    p.set("u_mvp", frame.mvp);
    p.set("u_eye", frame.eye);
    p.set("u_feature_size_sq", mesh.feature_size() * mesh.feature_size());
    p.set("u_viewport", frame.viewport);
    p.set("u_line_width", s.line_width);
    p.set("u_depth", 0);
    p.set("u_depth_params", glm::vec2(frame.projection[2][2], frame.projection[3][2]));
    p.set("u_normal_matrix", frame.normal_matrix);
    const float len = glm::length(s.light_dir);
    p.set("u_light", len > 0 ? s.light_dir / len : glm::vec3(0, 0, 1));
    p.set("u_hatching", int(s.hatching));
}

void LineRenderer::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s,
                        GLuint surface_depth_texture) {
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MAX);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, surface_depth_texture);

    // Contours, suggestive contours and hatching strokes: one pass over the triangles.
    if (s.lines.contours || s.lines.suggestive || s.hatching != Hatching::None) {
        ShaderProgram& p = s.hatching != Hatching::None ? isolines_hatching_ : isolines_;
        set_common(p, mesh, frame, s);
        p.set("u_hatch_spacing", s.hatch_spacing);
        p.set("u_stroke_length", s.hatch_stroke_length);
        p.set("u_stroke_width", s.hatch_stroke_width);
        p.set("u_contours", int(s.lines.contours));
        p.set("u_suggestive", int(s.lines.suggestive));
        p.set("u_sc_threshold", s.sc_threshold);
        p.set("u_fade", int(s.fade));
        mesh.draw_triangles();
    }
    if (s.lines.boundaries && mesh.boundary_edge_count() > 0) {
        set_common(boundaries_, mesh, frame, s);
        mesh.draw_boundary_edges();
    }
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

}  // namespace kappa::render
