#include "web/src/page_state.h"

#include "app/appearance_settings.h"
#include "app/cli_options.h"
#include "app/mesh_source.h"
#include "geometry/parallel/parallel.h"
#include "geometry/view/default_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace kappa::web {

void PageState::start(const std::string& canvas) {
    set_thread_count(1);  // no threads without SharedArrayBuffer, which a plain static server does not enable
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    attributes.antialias = false;  // the renderer multisamples its own surface pass; the canvas takes a blit
    attributes.depth = false;
    attributes.stencil = false;
    attributes.preserveDrawingBuffer = false;  // PNG downloads draw, then read the canvas in the same task
    context_ = emscripten_webgl_create_context(canvas.c_str(), &attributes);
    if (context_ <= 0) throw std::runtime_error("this browser gives no WebGL2 context");
    emscripten_webgl_make_context_current(context_);
    renderer_ = std::make_unique<render::Renderer>();
}

void PageState::open(const std::string& path) {
    Mesh input = app::load_mesh_or_default(path);
    if (input.face_count() == 0)
        throw std::runtime_error(app::mesh_display_name(path) + ": the mesh has no faces: nothing to draw");
    input_ = std::move(input);
    path_ = path;
    options_.camera.file_up = file_up_axis(path);  // glTF: +y
    drawing_.reset();
    shown_ = false;  // not the last mesh's fields meanwhile
    prepare();
    view_reset_ = true;
}

// The drawing opens in steps, one a slice of prepare(seconds) (app/mesh_drawing.h: the
// preparation and split, the fields, the scale space), so that the page shows its progress
// and stays alive between them.
void PageState::prepare() {
    drawing_.reset();
    if (input_)
        drawing_ = std::make_unique<app::MeshDrawing>(*input_, options_.settings, options_.smoothing,
                                                      app::MeshDrawing::InSteps{});
}

// Whatever is left of opening the drawing, at once (a download, a new view asked for).
app::MeshDrawing& PageState::open_drawing() {
    while (!open_step()) {
    }
    if (view_reset_) view_reset_ = false, reset_view();
    return *drawing_;
}

// A step that fails (its message is the page's error) leaves no drawing half open.
bool PageState::open_step() {
    try {
        return drawing_->open_step();
    } catch (...) {
        drawing_.reset();
        input_.reset();
        throw;
    }
}

void PageState::reset_view() {
    if (!drawing_) return;
    if (!drawing_->opened()) {  // when it is
        view_reset_ = true;
        return;
    }
    glm::vec3 center(0);
    const render::Camera c =
        app::make_camera(options_.camera, *drawing_, size_, &center);
    orbit_.set_view(c.view);
    orbit_.set_pivot(center);
    fov_ = c.fov_y_deg;
}

void PageState::set(const std::string& name, const std::string& value) {
    const app::AppearanceSetting* a = app::find_appearance_setting(name);
    if (!a) throw std::runtime_error("unknown setting '" + name + "'");
    render::RenderSettings s = options_.settings;
    if (a->flag && (value == "on" || value == "off")) s.*a->flag = value == "on";
    else if (!a->set || !a->set(s, value))
        throw std::runtime_error("--" + name + " expects " + a->expects + ", got '" + value + "'");
    // The crease angle and the detail decide how the mesh is prepared (app/mesh_drawing.h).
    const bool again = drawing_ && !drawing_->same_preparation(s, options_.smoothing);
    options_.settings = s;
    if (again) prepare();
}

void PageState::set_view(std::optional<ViewAngles> angles) {
    options_.camera.view = angles;
    reset_view();
}

void PageState::resize(int width, int height) {
    if (width < 1 || height < 1 || width > 8192 || height > 8192)
        throw std::runtime_error("--size " + std::to_string(width) + "x" + std::to_string(height) + " is out of range");
    if (glm::ivec2(width, height) == size_) return;
    size_ = {width, height};
    emscripten_set_canvas_element_size("#canvas", width, height);
}

bool PageState::prepare(double seconds) {
    if (!drawing_) return true;
    emscripten_webgl_make_context_current(context_);
    if (!drawing_->opened()) {
        if (open_step()) open_drawing();  // the requested view, now that there are bounds
        return false;
    }
    const bool done = drawing_->prepare_view_slice(*renderer_, camera(), size_, seconds);
    shown_ = shown_ || done;
    return done;
}

void PageState::draw() {
    emscripten_webgl_make_context_current(context_);
    const int w = size_.x, h = size_.y;
    if (!shown_) {
        const glm::vec4 b = options_.settings.background;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, w, h);
        glClearColor(b.r, b.g, b.b, b.a);
        glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    // As the desktop viewer's "fast while moving": no multisampling while the view moves (software
    // WebGL multisamples slowly), and three quarters of the resolution, stretched over the canvas
    // (SwiftShader's time goes with the pixels: bunny at 800x600 orbited at 9 to 11 frames a second
    // at full size); widths and spacings in pixels scaled alike, so the drawing looks the same. The
    // view at rest is drawn with the settings as they are.
    render::RenderSettings settings = options_.settings;
    int rw = w, rh = h;
    if (moving_) {
        constexpr float kMovingScale = 0.75f;
        settings.msaa = false;
        rw = std::max(1, int(std::lround(w * kMovingScale))), rh = std::max(1, int(std::lround(h * kMovingScale)));
        settings.line_width *= float(rh) / float(h);
        settings.hatch_spacing *= float(rh) / float(h);
    }
    renderer_->render_offscreen(camera(), settings, rw, rh);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, renderer_->offscreen_framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, rw, rh, 0, 0, w, h, GL_COLOR_BUFFER_BIT, rw == w ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void PageState::write(const std::string& path) {
    if (!drawing_) throw std::runtime_error(path + ": no mesh is open");
    emscripten_webgl_make_context_current(context_);
    open_drawing().write(*renderer_, camera(), options_.settings, size_, path);
    shown_ = true;
}

}  // namespace kappa::web
