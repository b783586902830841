#include "render/lines/line_renderer.h"


#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace kappa::render {

namespace {

std::vector<ShaderStage> line_program(std::vector<std::string> geometry_files, std::string defines = {}) {
    return {{GL_VERTEX_SHADER, {"common/mesh_attributes.glsl", "common/view_dependent.glsl", "lines/lines_vert.glsl"}},
            {GL_GEOMETRY_SHADER, std::move(geometry_files), std::move(defines)},
            {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}};
}

}  // namespace

LineRenderer::LineRenderer()
    : isolines_(line_program({"lines/line_quad.glsl", "lines/isolines_geom.glsl"})),
      isolines_highlights_(line_program({"lines/line_quad.glsl", "lines/isolines_geom.glsl"}, "#define KAPPA_HIGHLIGHTS\n")),
      boundaries_(line_program({"lines/line_quad.glsl", "lines/boundary_geom.glsl"})),
      curvature_lines_({{GL_VERTEX_SHADER, {"common/mesh_attributes.glsl", "lines/curvature_lines_vert.glsl"}},
                        {GL_GEOMETRY_SHADER, {"lines/line_quad.glsl", "lines/curvature_lines_geom.glsl"}},
                        {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}}),
      view_ridges_({{GL_VERTEX_SHADER, {"common/mesh_attributes.glsl", "common/view_curvature.glsl", "lines/view_ridges_vert.glsl"}},
                    {GL_GEOMETRY_SHADER, {"lines/line_quad.glsl", "lines/view_ridges_geom.glsl"}},
                    {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}}),
      level_lines_({{GL_VERTEX_SHADER, {"common/mesh_attributes.glsl", "lines/level_lines_vert.glsl"}},
                    {GL_GEOMETRY_SHADER, {"lines/line_quad.glsl", "lines/level_lines_geom.glsl"}},
                    {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}}),
      vectors_({{GL_VERTEX_SHADER, {"common/mesh_attributes.glsl", "lines/vectors_vert.glsl"}},
                {GL_GEOMETRY_SHADER, {"lines/line_quad.glsl", "lines/vectors_geom.glsl"}},
                {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}}),
      creases_({{GL_VERTEX_SHADER, {"lines/crease_vert.glsl"}},
                {GL_GEOMETRY_SHADER, {"lines/line_quad.glsl", "lines/crease_geom.glsl"}},
                {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}}) {}

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
    p.set("u_hidden_lines", int(s.hidden_lines));
}

void LineRenderer::begin_cpu_lines(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s) {
    pending_cpu_lines_ = std::async(std::launch::async, [this, &mesh, frame, s] { return cpu_lines_.prepare(mesh, frame, s); });
}

InkArea LineRenderer::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s, bool cpu_lines,
                           GLuint surface_depth_texture, GLuint coverage_texture,
                           const std::vector<WindowSegment>& strokes, const std::vector<float>* cpu_depth) {
    InkArea ink;
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MAX);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, surface_depth_texture);

    // Each pass draws every triangle, or with culling the runs of clusters
    // that can hold its lines (render/lines/cluster_culling.h).
    const float margin = 0.5f * s.line_width + 2.0f;  // pixels a line may reach beyond its centre
    auto draw_culled = [&](auto runs) {
        if (s.cull_clusters) mesh.draw_triangles(runs());
        else mesh.draw_triangles();
    };
    // Contours, suggestive contours, suggestive highlights and the Dw kr lines:
    // one pass over the triangles.
    const bool contours = s.lines.any_contours(), silhouette_only = s.lines.silhouette && !s.lines.contours;
    const bool highlights = s.lines.suggestive_highlights;
    if (cpu_lines) {
        // Every kind drawn by the four passes below.
        const CpuLines lines = pending_cpu_lines_.valid() ? pending_cpu_lines_.get() : cpu_lines_.prepare(mesh, frame, s);
        ink = cpu_lines_.draw(lines, strokes, frame, s, surface_depth_texture, coverage_texture, cpu_depth);
    } else if (contours || s.lines.suggestive || highlights || s.lines.dwkr) {
        ink.anywhere = true;
        // The variant that can also draw highlights and Dw kr lines only when they are on.
        ShaderProgram& p = highlights || s.lines.dwkr ? isolines_highlights_ : isolines_;
        set_common(p, mesh, frame, s);
        p.set("u_contours", int(contours));
        p.set("u_silhouette_only", int(silhouette_only));
        p.set("u_suggestive", int(s.lines.suggestive));
        p.set("u_sc_threshold", s.sc_threshold);
        p.set("u_highlights", int(highlights));
        p.set("u_sh_threshold", s.sh_threshold);
        p.set("u_dwkr", int(s.lines.dwkr));
        p.set("u_fade", int(s.fade));
        // One pixel spans 2 w / (P[1][1] height) model units at camera distance w.
        p.set("u_scale_tolerance", s.detail * 2.0f / (frame.projection[1][1] * frame.viewport.y));
        // Highlights need a zero of kr like suggestive contours, but no bound on
        // -Dw kr holds (its cot(theta) term grows without limit): no strength
        // test for them. The Dw kr lines can be anywhere in front.
        draw_culled([&] {
            return contour_pass_runs(mesh.clusters(), frame, contours, s.lines.suggestive || highlights,
                                     highlights ? -1e30f : s.sc_threshold, margin, s.lines.dwkr);
        });
    }
    // Ridges, valleys, parabolic and mean-zero lines.
    if (s.lines.curvature_lines() && !cpu_lines) {
        ink.anywhere = true;
        set_common(curvature_lines_, mesh, frame, s);
        curvature_lines_.set("u_parabolic", int(s.lines.parabolic));
        curvature_lines_.set("u_mean_zero", int(s.lines.mean_zero));
        curvature_lines_.set("u_ridges", int(s.lines.ridges));
        curvature_lines_.set("u_valleys", int(s.lines.valleys));
        curvature_lines_.set("u_rv_threshold", s.rv_threshold);
        curvature_lines_.set("u_feature_size", mesh.feature_size());
        curvature_lines_.set("u_fade", int(s.fade));
        draw_culled([&] {
            return curvature_line_runs(mesh.clusters(), frame, s.hidden_lines, margin, s.lines, s.rv_threshold);
        });
    }
    // Apparent ridges and principal highlights.
    if (s.lines.view_ridges() && !cpu_lines) {
        ink.anywhere = true;
        set_common(view_ridges_, mesh, frame, s);
        view_ridges_.set("u_apparent_ridges", int(s.lines.apparent_ridges));
        view_ridges_.set("u_principal_highlights", int(s.lines.principal_highlights));
        view_ridges_.set("u_ar_threshold", s.ar_threshold);
        view_ridges_.set("u_ph_threshold", s.ph_threshold);
        view_ridges_.set("u_fade", int(s.fade));
        view_ridges_.set("u_feature_size", mesh.feature_size());
        draw_culled([&] {
            return view_ridge_runs(mesh.clusters(), frame, s.hidden_lines, margin, s.lines, s.ph_threshold);
        });
    }
    // Isophotes (n.l levels, the light as the shading's, in model coordinates)
    // and topographic lines (height levels along y across the bounding sphere).
    if (s.lines.isophotes && s.isophote_count > 0 && !cpu_lines) {
        ink.anywhere = true;
        set_common(level_lines_, mesh, frame, s);
        level_lines_.set("u_kind", 0);
        const glm::vec3 light = glm::normalize(glm::transpose(frame.normal_matrix) * camera_light_direction(s, frame));
        level_lines_.set("u_light_model", light);
        const LevelSet levels = isophote_level_set(s.isophote_count);
        level_lines_.set("u_first", levels.first);
        level_lines_.set("u_step", levels.step);
        level_lines_.set("u_count", levels.count);
        draw_culled([&] { return isophote_runs(mesh.clusters(), frame, s.hidden_lines, margin, light, levels); });
    }
    if (s.lines.topo && s.topo_count > 0 && !cpu_lines) {
        ink.anywhere = true;
        set_common(level_lines_, mesh, frame, s);
        level_lines_.set("u_kind", 1);
        const LevelSet levels = topo_level_set(mesh.bounds().center.y, mesh.bounds().radius, s.topo_count);
        level_lines_.set("u_first", levels.first);
        level_lines_.set("u_step", levels.step);
        level_lines_.set("u_count", levels.count);
        draw_culled([&] { return topo_runs(mesh.clusters(), frame, s.hidden_lines, margin, levels); });
    }
    // The GL passes below test against the depth texture: a depth drawn on the CPU goes there first.
    const bool glyphs = s.vectors != 0 && mesh.vertex_count() > 0;
    const bool creases = (s.lines.creases || contours) && mesh.crease_count() > 0;
    if (cpu_depth && cpu_depth->size() == size_t(frame.viewport.x) * size_t(frame.viewport.y) && (glyphs || creases)) {
        glBindTexture(GL_TEXTURE_2D, surface_depth_texture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, GLsizei(frame.viewport.x), GLsizei(frame.viewport.y), GL_DEPTH_COMPONENT,
                        GL_FLOAT, cpu_depth->data());
    }
    // Direction glyphs, 10 pixels long, at about one vertex per 600 pixels of the image.
    if (glyphs) {
        ink.anywhere = true;
        set_common(vectors_, mesh, frame, s);
        vectors_.set("u_vectors", s.vectors);
        vectors_.set("u_glyph", 10.0f);
        const size_t wanted = std::max<size_t>(1, size_t(frame.viewport.x * frame.viewport.y / 600.0f));
        vectors_.set("u_stride", int(std::max<size_t>(1, mesh.vertex_count() / wanted)));
        mesh.draw_points();
    }
    if (creases) {
        ink.anywhere = true;
        set_common(creases_, mesh, frame, s);
        creases_.set("u_creases", int(s.lines.creases));
        creases_.set("u_contours", int(contours));
        creases_.set("u_silhouette_only", int(silhouette_only));
        mesh.draw_creases();
    }
    if (s.lines.boundaries && mesh.boundary_edge_count() > 0 && !cpu_lines) {
        ink.anywhere = true;
        set_common(boundaries_, mesh, frame, s);
        mesh.draw_boundary_edges();
    }
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    return ink;
}

}  // namespace kappa::render
