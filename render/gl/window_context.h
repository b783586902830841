// A GLFW window with an OpenGL 3.3 core context (the viewer's counterpart of
// egl_context.h). Debian's GLFW is X11 only: without a display, create()
// throws ContextError with a one-line reason (platform.md).
#pragma once

#include "render/gl/egl_context.h"  // ContextError

#include <glm/vec2.hpp>

#include <memory>
#include <string>

struct GLFWwindow;

namespace kappa::render {

class WindowContext {
public:
    struct Options {
        int width = 1280, height = 800;  // window size in screen coordinates
        std::string title = "kappa";
        bool vsync = true;
        bool visible = true;
    };

    // Initialises GLFW, opens the window, makes its context current on this
    // thread and loads GL. Throws ContextError when there is no display or no
    // 3.3 core context.
    static std::unique_ptr<WindowContext> create(const Options& options);
    ~WindowContext();
    WindowContext(const WindowContext&) = delete;
    WindowContext& operator=(const WindowContext&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool should_close() const;
    void request_close();
    void swap_buffers();
    void set_title(const std::string& title);

    // Framebuffer size in pixels; on high-DPI screens larger than the window
    // size in screen coordinates (their ratio is pixel_ratio()).
    glm::ivec2 framebuffer_size() const;
    glm::ivec2 window_size() const;
    float pixel_ratio() const;  // framebuffer pixels per screen coordinate
    float content_scale() const;  // the monitor's UI scale (1 on a standard screen)

    const std::string& description() const { return description_; }

private:
    WindowContext() = default;
    GLFWwindow* window_ = nullptr;
    std::string description_;
};

}  // namespace kappa::render
