#include "render/surface_renderer.h"


namespace kappa::render {

SurfaceRenderer::SurfaceRenderer()
    : program_({{GL_VERTEX_SHADER, {"mesh_attributes.glsl", "colormap.glsl", "surface_vert.glsl"}},
                {GL_FRAGMENT_SHADER, {"colormap.glsl", "surface_frag.glsl"}}}) {}

void SurfaceRenderer::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s) {
    program_.use();
    program_.set("u_mvp", frame.mvp);
    program_.set("u_model_view", frame.model_view);
    program_.set("u_normal_matrix", frame.normal_matrix);
    program_.set("u_shading", int(s.shading));
    program_.set("u_light", camera_light_direction(s, frame));
    program_.set("u_colormap", int(s.colormap));
    program_.set("u_map_range", mesh.map_range(s.colormap));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    mesh.draw_triangles();
}

}  // namespace kappa::render
