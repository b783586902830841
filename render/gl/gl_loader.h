// Loads OpenGL entry points (glad) into the context that is current, from
// whichever window system made it: eglGetProcAddress headless,
// glfwGetProcAddress in a window.
#pragma once

#include <string>

namespace kappa::render {

// The core versions a context is asked for, highest first: 4.3 and later run
// the compute line path (render/lines/segment_buffer.h), 3.3 is the least the
// renderer needs. Drivers give exactly the version asked for or fail.
struct GLVersion {
    int major, minor;
};
inline constexpr GLVersion kCoreVersions[] = {{4, 6}, {4, 5}, {4, 4}, {4, 3}, {3, 3}};

using GlProcLoader = void (*(*)(const char* name))();

// Loads GL for the current context and checks that it offers OpenGL 3.3 core
// or newer; throws std::runtime_error with a one-line reason otherwise.
void load_gl(GlProcLoader loader);

// "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
std::string gl_description();

}  // namespace kappa::render
