// The hatching field of a view, rendered on the GPU and read back: per pixel
// the window angle of a principal direction (doubled: (cos 2a, sin 2a),
// times how well the direction is defined), the tone's darkness, and whether
// the surface there faces the eye; plus the surface depth. The streamlines
// of render/hatch_streamlines.h are traced over it on the CPU.
#pragma once

#include "render/frame_params.h"
#include "render/framebuffer.h"
#include "render/mesh_buffers.h"
#include "render/render_settings.h"
#include "render/shader_program.h"

#include <glm/vec4.hpp>

#include <vector>

namespace kappa::render {

struct HatchField {
    int width = 0, height = 0;
    std::vector<glm::vec4> texels;  // (cos 2a w, sin 2a w, darkness, facing), bottom row first
    std::vector<float> depth;       // window depth, 1 = background
    float p22 = 0, p32 = 0;         // projection terms: camera distance = p32 / (2 depth - 1 + p22)
};

class HatchFieldPass {
public:
    HatchFieldPass();  // compiles the shaders (GL context current)
    // direction: 1 = d1 (max), 2 = d2 (min). Leaves GL_FRAMEBUFFER unbound (0).
    HatchField draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings,
                    int direction);

private:
    ShaderProgram program_;
    Framebuffer fb_;
};

}  // namespace kappa::render
