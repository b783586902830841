// The one header through which render/ sees OpenGL: the glad 2 loader
// generated at build time for GL 4.6 core (cmake/render.cmake). The
// renderer needs 3.3; entry points the context lacks stay null, and
// GLAD_GL_VERSION_4_3 says whether the compute path can run.
// Built with emscripten (web/), OpenGL ES 3.0 (WebGL2) instead: see gles_compat.h.
#pragma once

#ifdef __EMSCRIPTEN__
#include "render/gl/gles_compat.h"
#else
#include <glad/gl.h>
namespace kappa::render {
inline constexpr bool kGles = false;  // desktop core GL: geometry shaders, depth readback
}
#endif
