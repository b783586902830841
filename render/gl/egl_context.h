// A headless OpenGL 3.3 core context through EGL, with no window, no X and
// no environment variables (platform.md): the EGL device platform first
// (a GPU server; hardware devices before software ones), then Mesa's
// surfaceless platform. Rendering goes to framebuffer objects.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace kappa::render {

class ContextError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class HeadlessContext {
public:
    // Creates the context, makes it current on this thread and loads GL.
    // Throws ContextError with a one-line reason when no platform works.
    static std::unique_ptr<HeadlessContext> create();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    // How the context was made and what renders, for logs:
    // "EGL device platform: llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 ..."
    const std::string& description() const { return description_; }

    // Makes the context current on the calling thread / releases it from the
    // calling thread, so that another thread can make it current (one thread
    // at a time: the Python module's callers). Throw ContextError on failure.
    void make_current();
    void release();

private:
    HeadlessContext() = default;
    void* display_ = nullptr;  // EGLDisplay
    void* context_ = nullptr;  // EGLContext
    std::string description_;
};

}  // namespace kappa::render
