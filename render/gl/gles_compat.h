// OpenGL ES 3.0 (WebGL2, the browser build in web/) in place of desktop core GL.
// ES 3.0 has no geometry or compute shaders and cannot read depth back, so
// in this build the renderer takes the paths a software GL takes, with the
// line families, creases and hatching strokes made on the CPU and drawn as
// screen-space quads (Renderer, kGles). The desktop entry points those other
// paths name are declared here so that the same sources compile; they are
// never called in this build.
#pragma once

#include <GLES3/gl3.h>

#include <cstdlib>

namespace kappa::render {
inline constexpr bool kGles = true;
}

// Never true here: the compute line path (render/lines/segment_buffer.h) needs GL 4.3.
#define GLAD_GL_VERSION_4_3 0

#define GL_GEOMETRY_SHADER 0x8DD9
#define GL_COMPUTE_SHADER 0x91B9
#define GL_TIMESTAMP 0x8E28
#define GL_SHADER_STORAGE_BUFFER 0x90D2
#define GL_DRAW_INDIRECT_BUFFER 0x8F3F
#define GL_DISPATCH_INDIRECT_BUFFER 0x90EE
#define GL_ATOMIC_COUNTER_BUFFER 0x92C0
#define GL_SHADER_STORAGE_BARRIER_BIT 0x00002000
#define GL_COMMAND_BARRIER_BIT 0x00000040
#define GL_BUFFER_UPDATE_BARRIER_BIT 0x00000200
#define GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT 0x00000001
#define GL_ELEMENT_ARRAY_BARRIER_BIT 0x00000002

namespace kappa::render::gles_compat {
// What a call of a desktop-only entry point would mean here: a path this build never takes.
[[noreturn]] inline void unavailable() { std::abort(); }
}  // namespace kappa::render::gles_compat

inline void glClearDepth(double depth) { glClearDepthf(float(depth)); }
inline void glDrawBuffer(GLenum buffer) { glDrawBuffers(1, &buffer); }
inline void glQueryCounter(GLuint, GLenum) { kappa::render::gles_compat::unavailable(); }
inline void glGetQueryObjectui64v(GLuint, GLenum, GLuint64*) { kappa::render::gles_compat::unavailable(); }
inline void glGetTexImage(GLenum, GLint, GLenum, GLenum, void*) { kappa::render::gles_compat::unavailable(); }
inline void glDispatchCompute(GLuint, GLuint, GLuint) { kappa::render::gles_compat::unavailable(); }
inline void glDispatchComputeIndirect(GLintptr) { kappa::render::gles_compat::unavailable(); }
inline void glMemoryBarrier(GLbitfield) { kappa::render::gles_compat::unavailable(); }
inline void glDrawArraysIndirect(GLenum, const void*) { kappa::render::gles_compat::unavailable(); }
inline void glGetBufferSubData(GLenum, GLintptr, GLsizeiptr, void*) { kappa::render::gles_compat::unavailable(); }
// ES 3.0 has no multi-draw: one draw a range (the culled surface pass draws a few hundred runs).
inline void glMultiDrawElements(GLenum mode, const GLsizei* counts, GLenum type, const void* const* offsets,
                                GLsizei drawcount) {
    for (GLsizei i = 0; i < drawcount; ++i) glDrawElements(mode, counts[i], type, offsets[i]);
}
