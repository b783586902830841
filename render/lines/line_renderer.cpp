#include "render/lines/line_renderer.h"

#include "geometry/parallel/parallel.h"


#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace kappa::render {

namespace {

ShaderProgram line_program(std::vector<std::string> geometry_files, std::string defines = {}) {
    return geometry_stage_program({{GL_VERTEX_SHADER,
             {"common/mesh_attributes.glsl", "common/view_dependent.glsl", "lines/line_vertex.glsl", "lines/lines_vert.glsl"}},
            {GL_GEOMETRY_SHADER, std::move(geometry_files), std::move(defines)},
            {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}});
}

// A per-triangle line family in the geometry stage: vertex_files compute its
// per-vertex quantities (ending with the family's vertex file, whose
// structure the geometry stage reads too), geometry_file feeds them to its
// extraction (extraction_file).
ShaderProgram triangle_program(std::vector<std::string> vertex_files, const std::string& vertex_stage,
                                          const std::string& extraction_file, const std::string& geometry_file,
                                          std::string defines = {}) {
    std::vector<std::string> vertex = {"common/mesh_attributes.glsl"};
    vertex.insert(vertex.end(), vertex_files.begin(), vertex_files.end());
    vertex.push_back(vertex_stage);
    std::vector<std::string> geometry = {"lines/segment_emit.glsl", "lines/line_quad.glsl", "lines/triangle_inputs.glsl",
                                         "common/mesh_attribute_values.glsl"};
    geometry.insert(geometry.end(), vertex_files.begin(), vertex_files.end());
    geometry.push_back(extraction_file);
    geometry.push_back(geometry_file);
    return geometry_stage_program({{GL_VERTEX_SHADER, std::move(vertex)},
                                   {GL_GEOMETRY_SHADER, std::move(geometry), std::move(defines)},
                                   {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}});
}

// The same family as a compute pass (shaders/lines/triangles_comp.glsl).
ShaderProgram compute_program(std::vector<std::string> vertex_files, const std::string& extraction_file,
                              const std::string& vertex_function, const std::string& extract_function,
                              const std::string& defines = {}) {
    std::vector<std::string> files = {"common/mesh_attribute_values.glsl", "common/mesh_vertex_fetch.glsl", "lines/segment_emit.glsl",
                                      "lines/segment_append.glsl", "lines/triangle_inputs.glsl"};
    files.insert(files.end(), vertex_files.begin(), vertex_files.end());
    files.push_back(extraction_file);
    files.push_back("lines/triangles_comp.glsl");
    return ShaderProgram({{GL_COMPUTE_SHADER, std::move(files),
                           defines + "#define KAPPA_VERTEX " + vertex_function + "\n#define KAPPA_EXTRACT " +
                               extract_function + "\n"}});
}

const std::vector<std::string> kLineVertex = {"common/view_dependent.glsl", "lines/line_vertex.glsl"};
const std::vector<std::string> kCurvatureVertex = {"lines/curvature_vertex.glsl"};
const std::vector<std::string> kViewRidgeVertex = {"common/view_curvature.glsl", "lines/view_ridge_vertex.glsl"};
const std::vector<std::string> kLevelVertex = {"lines/level_vertex.glsl"};

}  // namespace

LineRenderer::LineRenderer()
    : isolines_(triangle_program(kLineVertex, "lines/lines_vert.glsl", "lines/isolines.glsl", "lines/isolines_geom.glsl")),
      isolines_highlights_(triangle_program(kLineVertex, "lines/lines_vert.glsl", "lines/isolines.glsl",
                                            "lines/isolines_geom.glsl", "#define KAPPA_HIGHLIGHTS\n")),
      boundaries_(line_program({"lines/segment_emit.glsl", "lines/line_quad.glsl", "common/mesh_attribute_values.glsl",
                                "common/view_dependent.glsl", "lines/line_vertex.glsl", "lines/edge_inputs.glsl",
                                "lines/boundary_lines.glsl", "lines/boundary_geom.glsl"})),
      curvature_lines_(triangle_program(kCurvatureVertex, "lines/curvature_lines_vert.glsl", "lines/curvature_lines.glsl",
                                        "lines/curvature_lines_geom.glsl")),
      view_ridges_(triangle_program(kViewRidgeVertex, "lines/view_ridges_vert.glsl", "lines/view_ridges.glsl",
                                    "lines/view_ridges_geom.glsl")),
      level_lines_(triangle_program(kLevelVertex, "lines/level_lines_vert.glsl", "lines/level_lines.glsl",
                                    "lines/level_lines_geom.glsl")),
      vectors_(geometry_stage_program(
          {{GL_VERTEX_SHADER, {"common/mesh_attributes.glsl", "lines/vectors_vert.glsl"}},
           {GL_GEOMETRY_SHADER, {"lines/segment_emit.glsl", "lines/line_quad.glsl", "lines/vectors_geom.glsl"}},
           {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}})),
      creases_(geometry_stage_program(
          {{GL_VERTEX_SHADER, {"lines/crease_vert.glsl"}},
           {GL_GEOMETRY_SHADER,
            {"lines/segment_emit.glsl", "lines/line_quad.glsl", "lines/edge_inputs.glsl", "lines/crease_lines.glsl",
             "lines/crease_geom.glsl"}},
           {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}})) {
    if (SegmentBuffer::supported()) compute_ = std::make_unique<ComputeFamilies>();
}

// The per-triangle families as compute passes, and the buffer their segments go to.
struct LineRenderer::ComputeFamilies {
    ShaderProgram isolines = compute_program(kLineVertex, "lines/isolines.glsl", "line_vertex", "extract_isolines",
                                             "#define KAPPA_HIGHLIGHTS\n");
    ShaderProgram curvature_lines =
        compute_program(kCurvatureVertex, "lines/curvature_lines.glsl", "curvature_vertex", "extract_curvature_lines");
    ShaderProgram view_ridges =
        compute_program(kViewRidgeVertex, "lines/view_ridges.glsl", "view_ridge_vertex", "extract_view_ridges");
    ShaderProgram level_lines =
        compute_program(kLevelVertex, "lines/level_lines.glsl", "level_vertex", "extract_level_lines");
    // The per-edge families (shaders/lines/edges_comp.glsl).
    ShaderProgram boundaries = ShaderProgram({{GL_COMPUTE_SHADER,
                                               {"common/mesh_attribute_values.glsl", "common/mesh_vertex_fetch.glsl",
                                                "lines/segment_emit.glsl", "lines/segment_append.glsl",
                                                "lines/edge_inputs.glsl", "lines/boundary_lines.glsl",
                                                "lines/edges_comp.glsl"},
                                               "#define KAPPA_BOUNDARIES\n"}});
    ShaderProgram creases = ShaderProgram({{GL_COMPUTE_SHADER,
                                            {"lines/segment_emit.glsl", "lines/segment_append.glsl",
                                             "lines/edge_inputs.glsl", "lines/crease_lines.glsl",
                                             "lines/edges_comp.glsl"}}});
    SegmentBuffer segments;
};

LineRenderer::~LineRenderer() {
    if (timestamps_[0]) glDeleteQueries(3, timestamps_);
}

SegmentBuffer* LineRenderer::segment_buffer() { return compute_ ? &compute_->segments : nullptr; }

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
    // With one thread (the browser build) they are made when draw() asks for them.
    const auto policy = thread_count() > 1 ? std::launch::async : std::launch::deferred;
    pending_cpu_lines_ = std::async(policy, [this, &mesh, frame, s] { return cpu_lines_.prepare(mesh, frame, s); });
}

InkArea LineRenderer::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s,
                           LineExtraction path, GLuint surface_depth_texture, GLuint coverage_texture,
                           const std::vector<WindowSegment>& strokes, const std::vector<float>* cpu_depth) {
    InkArea ink;
    if (gpu_timing_) {
        if (!timestamps_[0]) glGenQueries(3, timestamps_);
        glQueryCounter(timestamps_[0], GL_TIMESTAMP);
    }
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MAX);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, surface_depth_texture);

    const bool cpu_lines = path == LineExtraction::Cpu;
    const bool compute = path == LineExtraction::Compute && compute_;
    // Each per-triangle family runs over every triangle, or with culling the
    // runs of clusters that can hold its lines (render/lines/cluster_culling.h):
    // in the geometry stage (gs, drawn at once) or as a compute pass (cs,
    // appending to the segment buffer drawn after the last family).
    const float margin = 0.5f * s.line_width + 2.0f;  // pixels a line may reach beyond its centre
    auto run_family = [&](ShaderProgram& gs, ShaderProgram& cs, auto set_uniforms, auto runs) {
        ink.anywhere = true;
        ShaderProgram& p = compute ? cs : gs;
        set_common(p, mesh, frame, s);
        set_uniforms(p);
        if (!compute) {
            if (s.cull_clusters) mesh.draw_triangles(runs());
            else mesh.draw_triangles();
            return;
        }
        const std::vector<FaceRun> all = {{0, uint32_t(mesh.face_count())}};
        compute_->segments.dispatch(p, s.cull_clusters ? runs() : all, mesh.vertex_buffer(), mesh.triangle_buffer());
    };
    // Contours, suggestive contours, suggestive highlights and the Dw kr lines:
    // one pass over the triangles.
    const bool contours = s.lines.any_contours(), silhouette_only = s.lines.silhouette && !s.lines.contours;
    const bool highlights = s.lines.suggestive_highlights;
    const bool creases = (s.lines.creases || contours) && mesh.crease_count() > 0;
    const bool boundaries = s.lines.boundaries && mesh.boundary_edge_count() > 0 && !cpu_lines;
    // With the compute path the families run until the segment buffer held
    // them all (a frame that asked for more grows it; an image for a file
    // is then drawn again, a viewer's frame is not waited for).
    for (int attempt = 0; attempt < 2 && !cpu_lines; ++attempt) {
        if (compute) compute_->segments.begin(mesh.face_count());
        if (contours || s.lines.suggestive || highlights || s.lines.dwkr) {
            // The geometry stage's variant that can also draw highlights and Dw kr lines only when they are on.
            run_family(highlights || s.lines.dwkr ? isolines_highlights_ : isolines_, compute_ ? compute_->isolines : isolines_,
                       [&](ShaderProgram& p) {
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
                       },
                       // Highlights need a zero of kr like suggestive contours, but no bound on
                       // -Dw kr holds (its cot(theta) term grows without limit): no strength
                       // test for them. The Dw kr lines can be anywhere in front.
                       [&] {
                           return contour_pass_runs(mesh.clusters(), frame, contours, s.lines.suggestive || highlights,
                                                    highlights ? -1e30f : s.sc_threshold, margin, s.lines.dwkr);
                       });
        }
        // Ridges, valleys, parabolic and mean-zero lines.
        if (s.lines.curvature_lines()) {
            run_family(curvature_lines_, compute_ ? compute_->curvature_lines : curvature_lines_,
                       [&](ShaderProgram& p) {
                           p.set("u_parabolic", int(s.lines.parabolic));
                           p.set("u_mean_zero", int(s.lines.mean_zero));
                           p.set("u_ridges", int(s.lines.ridges));
                           p.set("u_valleys", int(s.lines.valleys));
                           p.set("u_rv_threshold", s.rv_threshold);
                           p.set("u_feature_size", mesh.feature_size());
                           p.set("u_fade", int(s.fade));
                       },
                       [&] {
                           return curvature_line_runs(mesh.clusters(), frame, s.hidden_lines, margin, s.lines,
                                                      s.rv_threshold);
                       });
        }
        // Apparent ridges and principal highlights.
        if (s.lines.view_ridges()) {
            run_family(view_ridges_, compute_ ? compute_->view_ridges : view_ridges_,
                       [&](ShaderProgram& p) {
                           p.set("u_apparent_ridges", int(s.lines.apparent_ridges));
                           p.set("u_principal_highlights", int(s.lines.principal_highlights));
                           p.set("u_ar_threshold", s.ar_threshold);
                           p.set("u_ph_threshold", s.ph_threshold);
                           p.set("u_fade", int(s.fade));
                           p.set("u_feature_size", mesh.feature_size());
                       },
                       [&] {
                           return view_ridge_runs(mesh.clusters(), frame, s.hidden_lines, margin, s.lines,
                                                  s.ph_threshold);
                       });
        }
        // Isophotes (n.l levels, the light as the shading's, in model coordinates)
        // and topographic lines (height levels along y across the bounding sphere).
        if (s.lines.isophotes && s.isophote_count > 0) {
            const glm::vec3 light =
                glm::normalize(glm::transpose(frame.normal_matrix) * camera_light_direction(s, frame));
            const LevelSet levels = isophote_level_set(s.isophote_count);
            run_family(level_lines_, compute_ ? compute_->level_lines : level_lines_,
                       [&](ShaderProgram& p) {
                           p.set("u_kind", 0);
                           p.set("u_light_model", light);
                           p.set("u_first", levels.first);
                           p.set("u_step", levels.step);
                           p.set("u_count", levels.count);
                       },
                       [&] { return isophote_runs(mesh.clusters(), frame, s.hidden_lines, margin, light, levels); });
        }
        if (s.lines.topo && s.topo_count > 0) {
            const LevelSet levels = topo_level_set(mesh.bounds().center.y, mesh.bounds().radius, s.topo_count);
            run_family(level_lines_, compute_ ? compute_->level_lines : level_lines_,
                       [&](ShaderProgram& p) {
                           p.set("u_kind", 1);
                           p.set("u_first", levels.first);
                           p.set("u_step", levels.step);
                           p.set("u_count", levels.count);
                       },
                       [&] { return topo_runs(mesh.clusters(), frame, s.hidden_lines, margin, levels); });
        }
        // Creases and boundaries, one invocation an edge.
        if (compute && creases) {
            ShaderProgram& p = compute_->creases;
            set_common(p, mesh, frame, s);
            p.set("u_creases", int(s.lines.creases));
            p.set("u_contours", int(contours));
            p.set("u_silhouette_only", int(silhouette_only));
            compute_->segments.dispatch_items(p, uint32_t(mesh.crease_count()), 0, mesh.crease_buffer());
        }
        if (compute && boundaries) {
            set_common(compute_->boundaries, mesh, frame, s);
            compute_->segments.dispatch_items(compute_->boundaries, uint32_t(mesh.boundary_edge_count()),
                                              mesh.vertex_buffer(), mesh.boundary_edge_buffer());
        }
        if (!compute || compute_->segments.finish(complete_frames_)) break;
    }
    if (gpu_timing_) glQueryCounter(timestamps_[1], GL_TIMESTAMP);
    if (compute) compute_->segments.draw(frame, s.hidden_lines);
    if (gpu_timing_) {
        glQueryCounter(timestamps_[2], GL_TIMESTAMP);
        GLuint64 t[3] = {0, 0, 0};
        for (int i = 0; i < 3; ++i) glGetQueryObjectui64v(timestamps_[i], GL_QUERY_RESULT, &t[i]);
        gpu_times_ = {double(t[1] - t[0]) * 1e-6, double(t[2] - t[1]) * 1e-6};
    }
    if (cpu_lines) {
        // Every kind drawn by the passes above.
        const CpuLines lines = pending_cpu_lines_.valid() ? pending_cpu_lines_.get() : cpu_lines_.prepare(mesh, frame, s);
        ink = cpu_lines_.draw(lines, strokes, frame, s, surface_depth_texture, coverage_texture, cpu_depth);
    }
    if (creases || boundaries) ink.anywhere = true;  // after the CPU lines' own ink area
    // The GL passes below test against the depth texture: a depth drawn on the CPU goes there first.
    // OpenGL ES: no geometry stage for glyphs; creases came with the CPU lines (gles_compat.h).
    const bool glyphs = s.vectors != 0 && mesh.vertex_count() > 0 && !kGles;
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
    if (creases && !compute && !kGles) {
        set_common(creases_, mesh, frame, s);
        creases_.set("u_creases", int(s.lines.creases));
        creases_.set("u_contours", int(contours));
        creases_.set("u_silhouette_only", int(silhouette_only));
        mesh.draw_creases();
    }
    if (boundaries && !compute) {
        set_common(boundaries_, mesh, frame, s);
        mesh.draw_boundary_edges();
    }
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    return ink;
}

}  // namespace kappa::render
