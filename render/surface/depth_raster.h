// The surface's depth drawn on the CPU, for software GL when the surface is
// the paper (surface_is_background): the lines need only its depth, and
// llvmpipe sets up every triangle on the calling thread. The triangles are
// those draw_surface_triangles sends (surface_triangles: front faces of the
// clusters in view and, within the holes' rectangle, the back faces that can
// show through them; or every face), clipped to the view volume and filled by
// the GL's rules: pixel centres at (x + 1/2, y + 1/2), window depth
// interpolated linearly across the window, the nearest kept (GL_LESS
// against a clear of 1). Edges shared by two triangles are filled by one
// of them (a top-left rule), so no pixel falls between.
//
// Ranges of faces are drawn in parallel, each into its own buffer, and the
// buffers merged by the minimum: the nearest depth does not depend on the
// order, so the result is the same for any thread count.
#pragma once

#include "render/camera/frame_params.h"
#include "render/fields/mesh_buffers.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace kappa::render {

class DepthRaster {
public:
    // Window depths of the frame's viewport (the bottom row first, as
    // glReadPixels gives them; 1 where no face is), valid until the next call.
    // cull: as draw_surface_triangles' (false: every face, no face culling).
    const std::vector<float>& draw(const MeshBuffers& mesh, const FrameParams& frame, bool cull);

private:
    // Per vertex, kept between frames: the view-volume planes it is beyond
    // (bits), window position (x, y pixels, depth) where inside them all.
    std::vector<uint8_t> outside_;
    std::vector<glm::vec3> window_;
    // Per range of faces (the first is the result), kept between frames with
    // the rectangle each last drew in (x0, y0, x1, y1, the end exclusive):
    // only that is cleared again.
    std::vector<std::vector<float>> buffers_;
    std::vector<glm::ivec4> drawn_;
    int width_ = 0, height_ = 0;
};

}  // namespace kappa::render
