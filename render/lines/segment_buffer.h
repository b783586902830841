// The compute path of the line passes (--line-extraction compute): each
// per-triangle line family runs as a compute pass over the faces of the
// clusters that can hold its lines (shaders/lines/triangles_comp.glsl), with
// the same extraction functions as its geometry shader, and appends its
// segments to one buffer (shaders/lines/segment_append.glsl: an atomic
// counter that is the instance count of an indirect draw). All of a frame's
// segments are then drawn by one indirect draw of instanced screen-space
// quads (shaders/lines/segment_quads_vert.glsl, the CPU path's quad shader)
// with the same fragment stage as every line. Needs GL 4.3 (compute shaders,
// storage buffers).
//
// The buffer holds `capacity` segments; a frame that makes more draws the
// first `capacity` of them (in no particular order) and the buffer grows for
// the next frame. finish(wait = true) checks at once and lets the caller
// draw the frame again (an image written to a file must be complete).
#pragma once

#include "render/camera/frame_params.h"
#include "render/gl/gl.h"
#include "render/gl/shader_program.h"
#include "render/lines/cluster_culling.h"

#include <cstdint>
#include <vector>

namespace kappa::render {

class SegmentBuffer {
public:
    // Whether the current context can run the compute path (GL 4.3 or later).
    static bool supported();

    SegmentBuffer();  // GL context current; supported()
    ~SegmentBuffer();
    SegmentBuffer(const SegmentBuffer&) = delete;
    SegmentBuffer& operator=(const SegmentBuffer&) = delete;

    // Starts a frame: no segments. face_count: the mesh's, for the first capacity.
    void begin(size_t face_count);
    // Runs the compute program `p` (in use, its uniforms set) over the faces of
    // `runs`; vertex_buffer, triangle_buffer: the mesh's (render/fields/mesh_buffers.h).
    void dispatch(ShaderProgram& p, const std::vector<FaceRun>& runs, GLuint vertex_buffer, GLuint triangle_buffer);
    // Runs the compute program `p` once for each of `count` items (edges:
    // shaders/lines/edges_comp.glsl), item_buffer bound as storage 1 and
    // vertex_buffer (or 0) as storage 0.
    void dispatch_items(ShaderProgram& p, uint32_t count, GLuint vertex_buffer, GLuint item_buffer);
    // Clamps the draw to the capacity. Returns false when the frame made more
    // segments than the buffer holds; with wait = false that is only known
    // from an earlier frame (no stall), and the buffer grows for the next one.
    bool finish(bool wait);
    // Draws the frame's segments into the bound framebuffer (blending set by the caller):
    // the quad program's uniforms u_viewport, u_depth, u_depth_params and u_hidden_lines are set here.
    void draw(const FrameParams& frame, bool hidden_lines);
    uint32_t capacity() const { return capacity_; }
    // Sets the capacity now, dropping the segments held (for tests of the growth).
    void set_capacity(uint32_t segments) { grow(segments); }

private:
    void grow(uint32_t segments);
    ShaderProgram count_program_, quad_program_;
    GLuint runs_buffer_ = 0, segments_buffer_ = 0, draw_buffer_ = 0, quad_vao_ = 0;
    GLuint readback_buffer_ = 0;  // a frame's count, copied out for finish(false)'s later look
    uint32_t capacity_ = 0;
    GLsync pending_check_ = nullptr;  // signalled once readback_buffer_ holds a frame's count
};

}  // namespace kappa::render
