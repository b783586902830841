#include "gl_session.h"

#include "render/gl/egl_context.h"

namespace kappa::python {

namespace {

struct Session {
    std::mutex mutex;
    std::unique_ptr<render::HeadlessContext> context;
    std::unique_ptr<render::Renderer> renderer;
    GlStats stats;
};

// Never destroyed: tearing EGL down from static destructors at interpreter
// exit can crash; the process's end frees it.
Session& session() {
    static Session* s = new Session;
    return *s;
}

}  // namespace

CurrentRenderer::CurrentRenderer() : lock_(session().mutex) {
    Session& s = session();
    if (!s.context) {
        s.context = render::HeadlessContext::create();  // current on this thread
        ++s.stats.contexts_created;
        s.stats.description = s.context->description();
        s.renderer = std::make_unique<render::Renderer>();
    } else {
        s.context->make_current();
    }
    ++s.stats.drawings;
}

CurrentRenderer::~CurrentRenderer() {
    try {
        session().context->release();
    } catch (...) {  // nothing to do: the next call makes it current again
    }
}

render::Renderer& CurrentRenderer::renderer() { return *session().renderer; }

GlStats gl_stats() {
    Session& s = session();
    std::lock_guard<std::mutex> lock(s.mutex);
    return s.stats;
}

}  // namespace kappa::python
