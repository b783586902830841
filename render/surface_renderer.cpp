#include "render/surface_renderer.h"


namespace kappa::render {

SurfaceRenderer::SurfaceRenderer()
    : program_({{GL_VERTEX_SHADER, {"mesh_attributes.glsl", "colormap.glsl", "surface_vert.glsl"}},
                {GL_FRAGMENT_SHADER, {"colormap.glsl", "surface_frag.glsl"}}}),
      plain_({{GL_VERTEX_SHADER, {"surface_plain_vert.glsl"}},
              {GL_FRAGMENT_SHADER, {"colormap.glsl", "surface_frag.glsl"}}}) {}

void SurfaceRenderer::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s) {
    ShaderProgram& p = s.colormap == ColorMap::None ? plain_ : program_;
    p.use();
    p.set("u_mvp", frame.mvp);
    p.set("u_normal_matrix", frame.normal_matrix);
    p.set("u_shading", int(s.shading));
    p.set("u_light", camera_light_direction(s, frame));
    p.set("u_colormap", int(s.colormap));
    p.set("u_map_range", mesh.map_range(s.colormap));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    mesh.draw_triangles();
}

}  // namespace kappa::render
