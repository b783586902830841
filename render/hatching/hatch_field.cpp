#include "render/hatching/hatch_field.h"

#include "geometry/parallel/parallel.h"
#include "render/surface/surface_renderer.h"

#include <cmath>

namespace kappa::render {

HatchFieldPass::HatchFieldPass()
    : program_({{GL_VERTEX_SHADER, {"common/mesh_attributes.glsl", "hatching/window_directions.glsl", "hatching/hatch_field_vert.glsl"}},
                {GL_FRAGMENT_SHADER, {"hatching/hatch_field_frag.glsl"}}}) {}

HatchField HatchFieldPass::draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s) {
    const int w = int(frame.viewport.x), h = int(frame.viewport.y);
    if (!fb_.matches(w, h, 0)) fb_ = Framebuffer({w, h, 0, GL_RGBA8, true});
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
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    draw_surface_triangles(mesh, frame, back_face_culling_, false);  // the surface pass's visible faces
    HatchField field;
    field.width = w, field.height = h;
    const Image bytes = fb_.read(false);  // top row first; shaders/hatching/hatch_field_frag.glsl's layout
    field.directions.resize(size_t(w) * size_t(h));
    field.tone.resize(field.directions.size());
    // Angles come as bytes: their cosines and sines from a table (the same values).
    glm::vec2 unit[256];
    for (int k = 0; k < 256; ++k) {
        const float a = 2.0f * float(M_PI) * float(k) / 255.0f;
        unit[k] = glm::vec2(std::cos(a), std::sin(a));
    }
    parallel_for(size_t(h), [&](size_t row) {
        const int y = int(row);
        for (int x = 0; x < w; ++x) {
            const Rgba p = bytes.at(x, h - 1 - y);
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            const float w8 = float(p.b) / 255.0f;
            field.directions[i] = w8 * glm::vec4(unit[p.r], unit[p.g]);
            field.tone[i] = p.a == 0 ? glm::vec2(0) : glm::vec2(float(p.a - 1) / 254.0f, 1.0f);
        }
    }, 16);
    // OpenGL ES (the browser) cannot read depth back: the same faces' depth drawn on the CPU.
    field.depth = kGles ? depth_raster_.draw(mesh, frame, back_face_culling_) : fb_.read_depth();
    field.p22 = frame.projection[2][2], field.p32 = frame.projection[3][2];
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return field;
}

}  // namespace kappa::render
