#include "render/gl/egl_context.h"

#include "render/gl/gl_loader.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <vector>

namespace kappa::render {

namespace {

bool has_extension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

struct Attempt {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    std::string error;  // why it failed
};

// Initialises `display` and creates a current core context on it: the
// highest version the driver gives, 4.6 down to 3.3 (4.3 and later run the
// compute line path, render/lines/segment_buffer.h).
Attempt make_context(EGLDisplay display) {
    Attempt a;
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
        a.error = "eglInitialize failed";
        return a;
    }
    a.display = display;
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE,    EGL_PBUFFER_BIT,  EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                     EGL_RED_SIZE,        8,                EGL_GREEN_SIZE,      8,
                                     EGL_BLUE_SIZE,       8,                EGL_ALPHA_SIZE,      8,
                                     EGL_DEPTH_SIZE,      24,               EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, config_attribs, &config, 1, &count) || count == 0) {
        // Surfaceless displays may offer configs without pbuffer support.
        const EGLint relaxed[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        if (!eglChooseConfig(display, relaxed, &config, 1, &count) || count == 0) {
            a.error = "no EGL config supports desktop OpenGL";
            return a;
        }
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        a.error = "eglBindAPI(EGL_OPENGL_API) failed";
        return a;
    }
    for (const GLVersion v : kCoreVersions) {
        const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, v.major, EGL_CONTEXT_MINOR_VERSION, v.minor,
                                          EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                          EGL_NONE};
        a.context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
        if (a.context != EGL_NO_CONTEXT) break;
    }
    if (a.context == EGL_NO_CONTEXT) {
        a.error = "could not create an OpenGL 3.3 core context";
        return a;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, a.context)) {
        eglDestroyContext(display, a.context);
        a.context = EGL_NO_CONTEXT;
        a.error = "eglMakeCurrent without a surface failed";
    }
    return a;
}

// EGL devices, hardware ones first (Mesa also lists a software device).
std::vector<EGLDeviceEXT> query_devices() {
    auto query = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto query_string =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    EGLint n = 0;
    if (!query || !query(0, nullptr, &n) || n <= 0) return {};
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(n));
    if (!query(n, devices.data(), &n)) return {};
    devices.resize(size_t(n));
    std::vector<EGLDeviceEXT> hardware, software;
    for (auto d : devices) {
        const char* ext = query_string ? query_string(d, EGL_EXTENSIONS) : nullptr;
        (has_extension(ext, "EGL_MESA_device_software") ? software : hardware).push_back(d);
    }
    hardware.insert(hardware.end(), software.begin(), software.end());
    return hardware;
}

}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create() {
    const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!client_ext || !get_platform_display)
        throw ContextError("cannot create an OpenGL context: EGL has no platform extensions (is libEGL installed?)");

    std::string failures;
    auto finish = [](Attempt& a, const std::string& platform) {
        std::unique_ptr<HeadlessContext> ctx(new HeadlessContext);
        ctx->display_ = a.display;
        ctx->context_ = a.context;
        try {
            load_gl(eglGetProcAddress);
        } catch (const std::exception& e) {
            throw ContextError(std::string("cannot use the OpenGL context: ") + e.what());
        }
        ctx->description_ = platform + ": " + gl_description();
        return ctx;
    };

    if (has_extension(client_ext, "EGL_EXT_platform_device")) {
        for (EGLDeviceEXT device : query_devices()) {
            Attempt a = make_context(get_platform_display(EGL_PLATFORM_DEVICE_EXT, device, nullptr));
            if (a.context != EGL_NO_CONTEXT) return finish(a, "EGL device platform");
            if (a.display != EGL_NO_DISPLAY) eglTerminate(a.display);
            failures = "device platform: " + a.error;
        }
    }
    if (has_extension(client_ext, "EGL_MESA_platform_surfaceless")) {
        Attempt a = make_context(get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
        if (a.context != EGL_NO_CONTEXT) return finish(a, "EGL surfaceless platform");
        if (a.display != EGL_NO_DISPLAY) eglTerminate(a.display);
        failures += std::string(failures.empty() ? "" : "; ") + "surfaceless platform: " + a.error;
    }
    throw ContextError("cannot create a headless OpenGL 3.3 context with EGL (" +
                       (failures.empty() ? std::string("no device or surfaceless platform") : failures) + ")");
}

void HeadlessContext::make_current() {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        throw ContextError("eglMakeCurrent failed: cannot use the OpenGL context on this thread");
}

void HeadlessContext::release() {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT))
        throw ContextError("eglMakeCurrent failed: cannot release the OpenGL context");
}

HeadlessContext::~HeadlessContext() {
    if (display_) {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_) eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
}

}  // namespace kappa::render
