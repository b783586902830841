// The functions the page's JavaScript calls (web/page/kappa-page.js), in C so
// that ccall finds them. Each returns 0 on success; on failure 1, and
// kappa_message() gives the one-line reason (for a file, "NAME: problem", as
// the command line prints it).
#include "web/src/page_state.h"
#include "web/src/settings_json.h"

#include "app/render_options.h"

#include <emscripten/emscripten.h>

#include <exception>
#include <string>

namespace {

kappa::web::PageState& page() {
    static kappa::web::PageState state;
    return state;
}

std::string& message() {
    static std::string text;
    return text;
}

// Runs `body`, keeping the message of what it threw.
template <typename Body>
int attempt(Body&& body) {
    try {
        body();
        message().clear();
        return 0;
    } catch (const std::exception& e) {
        message() = e.what();
    } catch (...) {
        message() = "unexpected failure";
    }
    return 1;
}

}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* kappa_message() { return message().c_str(); }

EMSCRIPTEN_KEEPALIVE int kappa_start(const char* canvas) { return attempt([&] { page().start(canvas); }); }

EMSCRIPTEN_KEEPALIVE int kappa_open(const char* path) { return attempt([&] { page().open(path); }); }

EMSCRIPTEN_KEEPALIVE int kappa_set(const char* name, const char* value) {
    return attempt([&] { page().set(name, value); });
}

// "AZ,EL" as --view takes it, or "" for the default view.
EMSCRIPTEN_KEEPALIVE int kappa_view(const char* angles) {
    return attempt([&] {
        const std::string text = angles;
        if (text.empty()) return page().set_view(std::nullopt);
        const auto angles = kappa::app::parse_view_angles(text);
        if (!angles)
            throw std::runtime_error("--view expects two numbers AZ,EL in degrees, EL in [-90, 90], got '" + text +
                                     "'");
        page().set_view(angles);
    });
}

EMSCRIPTEN_KEEPALIVE int kappa_resize(int width, int height) {
    return attempt([&] { page().resize(width, height); });
}

EMSCRIPTEN_KEEPALIVE int kappa_draw() { return attempt([&] { page().draw(); }); }

EMSCRIPTEN_KEEPALIVE int kappa_write(const char* path) { return attempt([&] { page().write(path); }); }

EMSCRIPTEN_KEEPALIVE void kappa_moving(int moving) { page().set_moving(moving != 0); }

// Works on the fields of the current view for about `ms` milliseconds (one
// slice: the page calls it again from its next task): 0 once they are
// uploaded, 2 while there is more to do, 1 on failure.
EMSCRIPTEN_KEEPALIVE int kappa_prepare(double ms) {
    bool done = false;
    if (attempt([&] { done = page().prepare(ms / 1000.0); })) return 1;
    return done ? 0 : 2;
}

// 1 when the fields of the current view are the ones drawn.
EMSCRIPTEN_KEEPALIVE int kappa_view_prepared() { return page().view_prepared() ? 1 : 0; }

// Mouse gestures in canvas pixels (x right, y down), as the desktop viewer's.
EMSCRIPTEN_KEEPALIVE void kappa_orbit(float x0, float y0, float x1, float y1) {
    page().orbit().orbit({x0, y0}, {x1, y1}, glm::vec2(page().size()));
}
EMSCRIPTEN_KEEPALIVE void kappa_pan(float x0, float y0, float x1, float y1) {
    page().orbit().pan({x0, y0}, {x1, y1}, glm::vec2(page().size()));
}
EMSCRIPTEN_KEEPALIVE void kappa_zoom(float steps, float x, float y) {
    page().orbit().zoom(steps, {x, y}, glm::vec2(page().size()));
}

// The settings table and the current values, for the panel (settings_json.h).
EMSCRIPTEN_KEEPALIVE const char* kappa_settings() {
    static std::string json;
    json = kappa::web::settings_json(page().settings());
    return json.c_str();
}

}  // extern "C"
