#include "render/hatch_field.h"

namespace kappa::render {

HatchFieldPass::HatchFieldPass()
    : program_({{GL_VERTEX_SHADER, {"mesh_attributes.glsl", "hatch_field_vert.glsl"}},
                {GL_FRAGMENT_SHADER, {"hatch_field_frag.glsl"}}}) {}

HatchField HatchFieldPass::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s,
                                int direction) {
    const int w = int(frame.viewport.x), h = int(frame.viewport.y);
    if (!fb_.matches(w, h, 0)) fb_ = Framebuffer({w, h, 0, GL_RGBA32F, true});
    glBindFramebuffer(GL_FRAMEBUFFER, fb_.id());
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    program_.use();
    program_.set("u_mvp", frame.mvp);
    program_.set("u_eye", frame.eye);
    program_.set("u_normal_matrix", frame.normal_matrix);
    program_.set("u_light", camera_light_direction(s, frame));
    program_.set("u_viewport", frame.viewport);
    program_.set("u_feature_size", mesh.feature_size());
    program_.set("u_direction", direction);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    mesh.draw_triangles();
    HatchField field;
    field.width = w, field.height = h;
    field.texels = fb_.read_float();
    field.depth = fb_.read_depth();
    field.p22 = frame.projection[2][2], field.p32 = frame.projection[3][2];
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return field;
}

}  // namespace kappa::render
