#include "render/gl/window_context.h"

#include "render/gl/gl.h"
#include "render/gl/gl_loader.h"

#include <GLFW/glfw3.h>

#include <stdexcept>

namespace kappa::render {

namespace {

std::string g_glfw_error;  // last message from GLFW's error callback

void remember_error(int, const char* message) { g_glfw_error = message ? message : "unknown GLFW error"; }

}  // namespace

std::unique_ptr<WindowContext> WindowContext::create(const Options& options) {
    glfwSetErrorCallback(remember_error);
    if (!glfwInit())
        throw ContextError("no display (DISPLAY is not set or cannot be opened: " + g_glfw_error +
                           "); use 'kappa render' to render headless");
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);  // high-DPI: a window of the same physical size
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_SAMPLES, 0);  // the renderer multisamples offscreen
    // The highest core version the driver gives (render/gl/gl_loader.h).
    GLFWwindow* window = nullptr;
    for (const GLVersion v : kCoreVersions) {
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, v.major);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, v.minor);
        window = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
        if (window) break;
    }
    if (!window) {
        const std::string reason = g_glfw_error;
        glfwTerminate();
        throw ContextError("could not open an OpenGL 3.3 core window (" + reason + ")");
    }
    std::unique_ptr<WindowContext> w(new WindowContext);
    w->window_ = window;
    glfwMakeContextCurrent(window);
    try {
        load_gl(reinterpret_cast<GlProcLoader>(glfwGetProcAddress));
    } catch (const std::runtime_error& e) {
        throw ContextError(e.what());
    }
    glfwSwapInterval(options.vsync ? 1 : 0);
    w->description_ = "GLFW window: " + gl_description();
    return w;
}

WindowContext::~WindowContext() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

bool WindowContext::should_close() const { return glfwWindowShouldClose(window_); }
void WindowContext::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void WindowContext::swap_buffers() { glfwSwapBuffers(window_); }
void WindowContext::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

glm::ivec2 WindowContext::framebuffer_size() const {
    glm::ivec2 s;
    glfwGetFramebufferSize(window_, &s.x, &s.y);
    return s;
}

glm::ivec2 WindowContext::window_size() const {
    glm::ivec2 s;
    glfwGetWindowSize(window_, &s.x, &s.y);
    return s;
}

float WindowContext::pixel_ratio() const {
    const glm::ivec2 fb = framebuffer_size(), win = window_size();
    return win.x > 0 ? float(fb.x) / float(win.x) : 1.0f;
}

float WindowContext::content_scale() const {
    float x = 1, y = 1;
    glfwGetWindowContentScale(window_, &x, &y);
    return x > 0 ? x : 1.0f;
}

}  // namespace kappa::render
