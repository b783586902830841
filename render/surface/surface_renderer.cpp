#include "render/surface/surface_renderer.h"

#include "render/hatching/shader_hatching.h"
#include "render/surface/back_face_culling.h"

namespace kappa::render {

bool surface_is_background(const RenderSettings& s) {
    return s.shading == Shading::None && s.colormap == ColorMap::None && s.background == glm::vec4(1.0f);
}

namespace {

// The surface's vertex stage with the window directions the shader hatching needs.
ShaderStage hatched_vertex_stage() {
    return {GL_VERTEX_SHADER,
            {"common/mesh_attributes.glsl", "common/colormap.glsl", "hatching/window_directions.glsl",
             "surface/surface_vert.glsl"},
            "#define KAPPA_HATCHING\n"};
}

}  // namespace

SurfaceRenderer::SurfaceRenderer()
    : program_({{GL_VERTEX_SHADER, {"common/mesh_attributes.glsl", "common/colormap.glsl", "surface/surface_vert.glsl"}},
                {GL_FRAGMENT_SHADER, {"common/colormap.glsl", "surface/surface_frag.glsl"}}}),
      plain_({{GL_VERTEX_SHADER, {"surface/surface_plain_vert.glsl"}},
              {GL_FRAGMENT_SHADER, {"common/colormap.glsl", "surface/surface_frag.glsl"}}}),
      paper_({{GL_VERTEX_SHADER, {"surface/surface_paper_vert.glsl"}}, {GL_FRAGMENT_SHADER, {"surface/surface_paper_frag.glsl"}}}),
      hatched_({hatched_vertex_stage(),
                {GL_FRAGMENT_SHADER, {"common/colormap.glsl", "hatching/shader_hatching.glsl", "surface/surface_frag.glsl"},
                 "#define KAPPA_HATCHING\n"}}),
      hatch_targets_({hatched_vertex_stage(),
                      {GL_FRAGMENT_SHADER, {"common/colormap.glsl", "surface/surface_frag.glsl"},
                       "#define KAPPA_HATCHING\n#define KAPPA_HATCH_TARGETS\n"}}) {}

void SurfaceRenderer::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s,
                           SurfaceHatching hatching) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    if (!shader_hatching(s)) hatching = SurfaceHatching::None;
    const bool hatched = hatching != SurfaceHatching::None;
    ShaderProgram& p = hatching == SurfaceHatching::Strokes ? hatched_
                       : hatching == SurfaceHatching::Targets ? hatch_targets_
                       : s.shading == Shading::None && s.colormap == ColorMap::None ? paper_  // depth is all that varies
                       : s.colormap == ColorMap::None                             ? plain_
                                                                                  : program_;
    p.use();
    p.set("u_mvp", frame.mvp);
    const bool depth_only = surface_is_background(s) && !hatched;  // the colour stays the cleared white
    if (depth_only) glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    if (&p != &paper_) {
        p.set("u_normal_matrix", frame.normal_matrix);
        p.set("u_shading", int(s.shading));
        p.set("u_light", camera_light_direction(s, frame));
        p.set("u_colormap", int(s.colormap));
        p.set("u_map_range", mesh.map_range(s.colormap));
    }
    if (hatched) {
        set_hatching_uniforms(p, s);
        p.set("u_line_color", s.line_color);
        p.set("u_viewport", frame.viewport);
        p.set("u_feature_size", mesh.feature_size());
    }
    draw_surface_triangles(mesh, frame, back_face_culling_, &p == &paper_);
    if (depth_only) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

SurfaceTriangles surface_triangles(const MeshBuffers& mesh, const FrameParams& frame, bool cull) {
    SurfaceTriangles t;
    BackFaceCulling culling = back_face_culling(mesh.back_faces(), mesh.bounds(), mesh.clusters(), frame);
    if (!culling.cull || !cull) {
        t.front = {{0, uint32_t(mesh.face_count())}};  // every face
        return t;
    }
    // Front faces everywhere, back faces only where a hole is seen (geometry/culling/back_faces.h).
    t.cull = true;
    t.mirrored = culling.mirrored;
    t.front = front_surface_runs(mesh.clusters(), frame);
    t.back = std::move(culling.back_runs);
    t.holes = culling.holes;
    return t;
}

void draw_surface_triangles(const MeshBuffers& mesh, const FrameParams& frame, bool cull, bool positions_only) {
    auto draw = [&](const std::vector<FaceRun>& runs) {
        if (positions_only) mesh.draw_triangle_positions(runs);
        else mesh.draw_triangles(runs);
    };
    const SurfaceTriangles t = surface_triangles(mesh, frame, cull);
    if (!t.cull) {
        draw(t.front);
        return;
    }
    glEnable(GL_CULL_FACE);
    glFrontFace(t.mirrored ? GL_CW : GL_CCW);
    glCullFace(GL_BACK);
    draw(t.front);
    if (!t.back.empty()) {
        glCullFace(GL_FRONT);
        glEnable(GL_SCISSOR_TEST);
        glScissor(t.holes.x, t.holes.y, t.holes.z, t.holes.w);
        draw(t.back);
        glDisable(GL_SCISSOR_TEST);
    }
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);
}

}  // namespace kappa::render
