// The hatching field of a view, rendered on the GPU and read back: per pixel
// the window angles of both principal directions (doubled: (cos 2a, sin 2a),
// times how well the directions are defined), the tone's darkness, and
// whether the surface there faces the eye; plus the surface depth. The streamlines
// of render/hatching/hatch_streamlines.h are traced over it on the CPU.
#pragma once

#include "render/camera/frame_params.h"
#include "render/gl/framebuffer.h"
#include "render/fields/mesh_buffers.h"
#include "render/render_settings.h"
#include "render/gl/shader_program.h"
#include "render/surface/depth_raster.h"

#include <glm/vec4.hpp>

#include <vector>

namespace kappa::render {

struct HatchField {
    int width = 0, height = 0;
    std::vector<glm::vec4> directions;  // (cos 2a1, sin 2a1, cos 2a2, sin 2a2) w, bottom row first
    std::vector<glm::vec2> tone;        // (darkness, 1 where the surface faces the eye, else 0)
    std::vector<float> depth;       // window depth, 1 = background
    float p22 = 0, p32 = 0;         // projection terms: camera distance = p32 / (2 depth - 1 + p22)
};

class HatchFieldPass {
public:
    HatchFieldPass();  // compiles the shaders (GL context current)
    // Leaves GL_FRAMEBUFFER unbound (0).
    HatchField draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings);
    void set_back_face_culling(bool on) { back_face_culling_ = on; }  // for tests: off draws every face

private:
    ShaderProgram program_;
    Framebuffer fb_;
    DepthRaster depth_raster_;  // OpenGL ES: the depth, which it cannot read back, drawn on the CPU
    bool back_face_culling_ = true;
};

}  // namespace kappa::render
