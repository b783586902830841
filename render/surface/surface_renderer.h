// Surface pass: fills colour and depth with the shaded surface (paper,
// Lambert, toon, hemisphere, Gooch; colour maps).
#pragma once

#include "render/camera/frame_params.h"
#include "render/fields/mesh_buffers.h"
#include "render/render_settings.h"
#include "render/gl/shader_program.h"

namespace kappa::render {

// True when the surface pass leaves every pixel the background's colour: a
// white unlit surface (no shading, no colour map) on opaque white. Its
// colour is then not written, and multisampling has no edge to smooth.
bool surface_is_background(const RenderSettings& settings);

// The triangles the surface pass sends: every face, or with `cull` (where
// render/surface/back_face_culling.h allows it) the front faces of the clusters in
// view and, within the holes' rectangle, the back faces that can show
// through them: the same depth either way.
struct SurfaceTriangles {
    bool cull = false;      // false: every face, no face culling
    bool mirrored = false;  // front faces are clockwise on screen
    std::vector<FaceRun> front, back;  // with cull: the runs drawn front faces only, back faces only
    glm::ivec4 holes{0};    // the back faces' rectangle (x, y, width, height; pixels, bottom-left origin)
};
SurfaceTriangles surface_triangles(const MeshBuffers& mesh, const FrameParams& frame, bool cull);

// Those triangles into the bound framebuffer, depth tested (the back faces
// scissored to the holes). positions_only: from the buffer of positions
// alone (MeshBuffers::draw_triangle_positions, the paper program). On the
// CPU: render/surface/depth_raster.h.
void draw_surface_triangles(const MeshBuffers& mesh, const FrameParams& frame, bool cull, bool positions_only);

enum class SurfaceHatching { None, Strokes, Targets };

class SurfaceRenderer {
public:
    SurfaceRenderer();  // compiles the shaders (GL context current)
    // Draws into the bound framebuffer with depth testing.
    // Back faces are culled where none can be seen (render/surface/back_face_culling.h).
    // hatching: with --hatch-style shader, Strokes draws the strokes of
    // shaders/hatching/shader_hatching.glsl into the surface's colour per
    // fragment (software GL: nothing else to do); Targets writes what they
    // need into draw buffers 1 and 2 (render/hatching/shader_hatching.h draws
    // them once a pixel: GPUs).
    void draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings,
              SurfaceHatching hatching = SurfaceHatching::None);
    void set_back_face_culling(bool on) { back_face_culling_ = on; }  // for tests: off draws every face

private:
    ShaderProgram program_;
    ShaderProgram plain_;  // without a colour map: reads only positions and normals
    ShaderProgram paper_;  // white paper, no colour map: positions only, nothing to interpolate
    ShaderProgram hatched_;  // any shading and colour map, with the shader hatching's strokes
    ShaderProgram hatch_targets_;  // the same, with the shader hatching's directions and tone as more targets
    bool back_face_culling_ = true;
};

}  // namespace kappa::render
