#include "render/lines/segment_buffer.h"

#include <algorithm>
#include <cstddef>

namespace kappa::render {

namespace {

// One segment: (end0, tolerance), (end1, width), (alpha0, alpha1, on_surface, exterior_only).
constexpr size_t kSegmentBytes = 12 * sizeof(float);
constexpr GLuint kDrawReset[5] = {4, 0, 0, 0, 0};  // a four-vertex strip, no instances; requested 0
constexpr int kGroupSize = 64;                      // local_size_x of triangles_comp.glsl
constexpr uint32_t kMaxGroupsX = 65535;             // the least GL_MAX_COMPUTE_WORK_GROUP_COUNT a GL 4.3 gives

// The instanced attributes of segment_quads_vert.glsl (KAPPA_INSTANCED) from a segment record.
void set_segment_attributes() {
    struct Attribute {
        GLuint location;
        int components;
        size_t offset;
    };
    const Attribute attributes[] = {{0, 3, 0}, {3, 1, 12}, {1, 3, 16}, {5, 1, 28}, {2, 2, 32}, {4, 1, 44}};
    for (const Attribute& a : attributes) {
        glEnableVertexAttribArray(a.location);
        glVertexAttribPointer(a.location, a.components, GL_FLOAT, GL_FALSE, GLsizei(kSegmentBytes),
                              reinterpret_cast<const void*>(a.offset));
        glVertexAttribDivisor(a.location, 1);
    }
}

// Enough groups of kGroupSize invocations for `invocations`, in rows of at most kMaxGroupsX
// (the shaders number them row by row).
void dispatch_groups(uint32_t invocations) {
    const uint32_t groups = (invocations + kGroupSize - 1) / kGroupSize;
    const uint32_t x = std::min(groups, kMaxGroupsX), y = (groups + x - 1) / x;
    glDispatchCompute(x, y, 1);
}

// How many segments a frame asked for (segment_count_comp.glsl), at `offset` in `buffer`.
GLuint read_requested(GLuint buffer, GLintptr offset) {
    GLuint requested = 0;
    glBindBuffer(GL_COPY_READ_BUFFER, buffer);
    glGetBufferSubData(GL_COPY_READ_BUFFER, offset, sizeof(GLuint), &requested);
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    return requested;
}
constexpr GLintptr kRequestedOffset = 4 * sizeof(GLuint);  // in the draw buffer

}  // namespace

bool SegmentBuffer::supported() { return GLAD_GL_VERSION_4_3 != 0; }

SegmentBuffer::SegmentBuffer()
    : count_program_({{GL_COMPUTE_SHADER, {"lines/segment_count_comp.glsl"}}}),
      quad_program_({{GL_VERTEX_SHADER, {"lines/segment_quads_vert.glsl"}, "#define KAPPA_INSTANCED\n"},
                     {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}}) {
    glGenBuffers(1, &runs_buffer_);
    glGenBuffers(1, &segments_buffer_);
    glGenBuffers(1, &draw_buffer_);
    glGenBuffers(1, &readback_buffer_);
    glBindBuffer(GL_COPY_WRITE_BUFFER, readback_buffer_);
    glBufferData(GL_COPY_WRITE_BUFFER, sizeof(GLuint), nullptr, GL_STREAM_READ);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, draw_buffer_);
    glBufferData(GL_DRAW_INDIRECT_BUFFER, sizeof(kDrawReset), kDrawReset, GL_DYNAMIC_COPY);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glGenVertexArrays(1, &quad_vao_);
    glBindVertexArray(quad_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, segments_buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(kSegmentBytes), nullptr, GL_DYNAMIC_COPY);
    set_segment_attributes();
    glBindVertexArray(0);
}

SegmentBuffer::~SegmentBuffer() {
    if (pending_check_) glDeleteSync(pending_check_);
    glDeleteVertexArrays(1, &quad_vao_);
    const GLuint buffers[] = {runs_buffer_, segments_buffer_, draw_buffer_, readback_buffer_};
    glDeleteBuffers(4, buffers);
}

void SegmentBuffer::grow(uint32_t segments) {
    capacity_ = segments;
    glBindBuffer(GL_ARRAY_BUFFER, segments_buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(size_t(capacity_) * kSegmentBytes), nullptr, GL_DYNAMIC_COPY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void SegmentBuffer::begin(size_t face_count) {
    // A quarter of the faces holds every line of the usual drawings (contours and suggestive contours
    // cross far fewer); the buffer grows when a frame asks for more.
    if (capacity_ == 0) grow(uint32_t(std::clamp<size_t>(face_count / 4, size_t(1) << 16, size_t(1) << 22)));
    if (pending_check_) {
        // The count an earlier frame copied out, once the GPU is done with it
        // (nothing writes that copy since: no stall); else looked at next frame.
        const GLenum state = glClientWaitSync(pending_check_, 0, 0);
        if (state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED || state == GL_WAIT_FAILED) {
            const GLuint requested = read_requested(readback_buffer_, 0);
            if (requested > capacity_) grow(requested + requested / 4);
            glDeleteSync(pending_check_);
            pending_check_ = nullptr;
        }
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, draw_buffer_);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(kDrawReset), kDrawReset);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void SegmentBuffer::dispatch(ShaderProgram& p, const std::vector<FaceRun>& runs, GLuint vertex_buffer,
                             GLuint triangle_buffer) {
    // (first face, faces before this run) for the search in triangles_comp.glsl.
    std::vector<uint32_t> table;
    table.reserve(2 * runs.size());
    uint32_t total = 0;
    for (const FaceRun& r : runs) {
        if (r.count == 0) continue;
        table.push_back(r.first);
        table.push_back(total);
        total += r.count;
    }
    if (total == 0) return;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, runs_buffer_);
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(table.size() * sizeof(uint32_t)), table.data(), GL_STREAM_DRAW);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, vertex_buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, triangle_buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, runs_buffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, segments_buffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, draw_buffer_);
    p.set("u_run_count", int(table.size() / 2));
    p.set("u_face_total", int(total));
    p.set("u_segment_capacity", int(capacity_));
    dispatch_groups(total);
}

void SegmentBuffer::dispatch_items(ShaderProgram& p, uint32_t count, GLuint vertex_buffer, GLuint item_buffer) {
    if (count == 0) return;
    if (vertex_buffer) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, vertex_buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, item_buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, segments_buffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, draw_buffer_);
    p.set("u_item_count", int(count));
    p.set("u_segment_capacity", int(capacity_));
    dispatch_groups(count);
}

bool SegmentBuffer::finish(bool wait) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    count_program_.use();
    count_program_.set("u_segment_capacity", int(capacity_));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, draw_buffer_);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (!wait) {
        if (!pending_check_) {
            glBindBuffer(GL_COPY_READ_BUFFER, draw_buffer_);
            glBindBuffer(GL_COPY_WRITE_BUFFER, readback_buffer_);
            glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, kRequestedOffset, 0, sizeof(GLuint));
            glBindBuffer(GL_COPY_READ_BUFFER, 0);
            glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
            pending_check_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        }
        return true;
    }
    const GLuint requested = read_requested(draw_buffer_, kRequestedOffset);
    if (requested <= capacity_) return true;
    grow(requested + requested / 4);
    return false;
}

void SegmentBuffer::draw(const FrameParams& frame, bool hidden_lines) {
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
    quad_program_.use();
    quad_program_.set("u_viewport", frame.viewport);
    quad_program_.set("u_depth", 0);
    quad_program_.set("u_depth_params", glm::vec2(frame.projection[2][2], frame.projection[3][2]));
    quad_program_.set("u_hidden_lines", int(hidden_lines));
    glBindVertexArray(quad_vao_);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, draw_buffer_);
    glDrawArraysIndirect(GL_TRIANGLE_STRIP, nullptr);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glBindVertexArray(0);
}

}  // namespace kappa::render
