// Mouse, keyboard and drop handling, shortcuts and file actions of the viewer.
#include "app/viewer/viewer_app.h"

#include "app/viewer/screenshot.h"
#include "render/camera/camera.h"
#include "render/fields/field_upload.h"
#include "render/image/image_writer.h"
#include "render/vector/vector_view.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace kappa::viewer {

namespace {

ViewerApp* app_of(GLFWwindow* w) { return static_cast<ViewerApp*>(glfwGetWindowUserPointer(w)); }

glm::vec2 cursor_of(GLFWwindow* w) {
    double x = 0, y = 0;
    glfwGetCursorPos(w, &x, &y);
    return {float(x), float(y)};
}

template <typename E>
E next_value(E value, size_t count) {
    return E((size_t(value) + 1) % count);
}

}  // namespace

// GLFW calls these with the ViewerApp as the window's user pointer; the
// friend-free way is a small struct of static functions forwarding to it.
struct ViewerCallbacks {
    static void button(GLFWwindow* w, int button, int action, int) {
        const bool pressed = action == GLFW_PRESS;
        if (pressed && ImGui::GetIO().WantCaptureMouse) return;  // a click on the panel
        app_of(w)->mouse_button(button, pressed, cursor_of(w));
    }
    static void cursor(GLFWwindow* w, double x, double y) { app_of(w)->cursor_moved({float(x), float(y)}); }
    static void scroll(GLFWwindow* w, double, double dy) {
        if (ImGui::GetIO().WantCaptureMouse) return;
        app_of(w)->scrolled(float(dy), cursor_of(w));
    }
    static void key(GLFWwindow* w, int key, int, int action, int mods) {
        if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard) return;
        if (const Shortcut* s = find_shortcut(key, mods)) app_of(w)->apply(s->action, s->line);
    }
    static void drop(GLFWwindow* w, int count, const char** paths) {
        if (count > 0) app_of(w)->open_mesh(paths[0]);
    }
    static void refresh(GLFWwindow* w) { app_of(w)->redraw_frames_ = 2; }
    static void resized(GLFWwindow* w, int, int) { app_of(w)->redraw_frames_ = 2; }
};

void ViewerApp::install_callbacks() {
    GLFWwindow* w = window_->handle();
    glfwSetWindowUserPointer(w, this);
    glfwSetMouseButtonCallback(w, ViewerCallbacks::button);
    glfwSetCursorPosCallback(w, ViewerCallbacks::cursor);
    glfwSetScrollCallback(w, ViewerCallbacks::scroll);
    glfwSetKeyCallback(w, ViewerCallbacks::key);
    glfwSetDropCallback(w, ViewerCallbacks::drop);
    glfwSetWindowRefreshCallback(w, ViewerCallbacks::refresh);
    glfwSetFramebufferSizeCallback(w, ViewerCallbacks::resized);
}

void ViewerApp::mouse_button(int button, bool pressed, glm::vec2 at) {
    redraw_frames_ = 2;
    if (pressed && drag_button_ < 0 &&
        (button == GLFW_MOUSE_BUTTON_LEFT || button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE)) {
        drag_button_ = button;
        last_cursor_ = at;
    } else if (!pressed && button == drag_button_) {
        drag_button_ = -1;
    }
}

void ViewerApp::cursor_moved(glm::vec2 at) {
    if (drag_button_ < 0) {
        redraw_frames_ = std::max(redraw_frames_, 1);  // ImGui hover highlights
        return;
    }
    const Area a = drawing_area();
    if (drag_button_ == GLFW_MOUSE_BUTTON_LEFT)
        orbit_.orbit(last_cursor_ - a.origin, at - a.origin, a.size);
    else
        orbit_.pan(last_cursor_ - a.origin, at - a.origin, a.size);
    last_cursor_ = at;
    redraw_frames_ = 2;
}

void ViewerApp::scrolled(float clicks, glm::vec2 at) {
    const Area a = drawing_area();
    orbit_.zoom(clicks, at - a.origin, a.size);
    redraw_frames_ = 2;
}

void ViewerApp::apply(Action action, const char* line) {
    using namespace render;
    RenderSettings& s = state_.settings;
    redraw_frames_ = 2;
    switch (action) {
    case Action::ToggleLine:
        if (const LineKind* k = line ? find_line_kind(line) : nullptr) s.lines.*(k->flag) = !(s.lines.*(k->flag));
        break;
    case Action::ToggleHiddenLines: s.hidden_lines = !s.hidden_lines; break;
    case Action::CycleShading: s.shading = next_value(s.shading, shading_names().size()); break;
    case Action::ToggleLightFrame: s.light_on_model = !s.light_on_model; break;
    case Action::CycleColorMap: s.colormap = next_value(s.colormap, colormap_names().size()); break;
    case Action::ToggleColorBar: s.colorbar = !s.colorbar; break;
    case Action::CycleHatching: s.hatching = next_value(s.hatching, hatching_names().size()); break;
    case Action::ToggleFade: s.fade = !s.fade; break;
    case Action::ToggleMsaa: s.msaa = !s.msaa; break;
    case Action::WiderLines: s.line_width = std::min(s.line_width * 1.25f, 64.0f); break;
    case Action::ThinnerLines: s.line_width = std::max(s.line_width / 1.25f, 0.5f); break;
    case Action::RaiseThreshold: s.sc_threshold = std::max(s.sc_threshold * 1.5f, 1e-3f); break;
    case Action::LowerThreshold: s.sc_threshold /= 1.5f; break;
    case Action::FitView:
        if (renderer_->mesh()) orbit_.fit(renderer_->mesh()->bounds(), drawing_area().size);
        break;
    case Action::ResetView:
        if (renderer_->mesh() && model_) orbit_.reset(renderer_->mesh()->bounds(), drawing_area().size, model_->view_direction, model_->view_up);
        break;
    case Action::TogglePanel: panel_.visible = !panel_.visible; break;
    case Action::ToggleHelp: panel_.help = !panel_.help; break;
    case Action::SaveScreenshot: {
        ScriptStep shot;  // at the end of the next frame, with the panel drawn
        shot.kind = ScriptStep::Screenshot;
        shot.flag = panel_.screenshot_with_panel;
        shot.value = panel_.screenshot_path;
        pending_screenshot_ = shot;
        break;
    }
    case Action::SaveView: save_view(panel_.view_path); break;
    case Action::LoadView: load_view(panel_.view_path); break;
    case Action::Quit: window_->request_close(); break;
    }
}

void ViewerApp::handle_panel(const PanelRequests& r) {
    if (r.fit) apply(Action::FitView);
    if (r.reset) apply(Action::ResetView);
    if (r.open) open_mesh(panel_.open_path);
    // The panel is drawn after the scene: a screenshot with it is taken at
    // the end of the frame, once the panel is in the image.
    if (r.screenshot) apply(Action::SaveScreenshot);
    if (r.save_view) save_view(panel_.view_path);
    if (r.load_view) load_view(panel_.view_path);
    if (r.recompute && model_) compute_.recompute(*model_, state_.smoothing);
}

void ViewerApp::open_mesh(const std::string& path) {
    if (path.empty()) return report("type a mesh path first", true);
    compute_.load(path, state_.smoothing, effective_detail() > 0, state_.settings.crease_angle);
    report("opening " + path);
}

void ViewerApp::save_screenshot(const std::string& path, bool with_panel) {
    try {
        if (const auto vector_format = render::vector_format_for(path)) {
            // The drawing area as strokes of exactly the fields drawn (the panel is not vector art).
            if (!model_ || !renderer_->mesh()) return report("no mesh to save yet", true);
            const Area a = drawing_area();
            const render::MeshBuffers& gpu = *renderer_->mesh();
            const std::vector<CreaseEdge> creases = render::crease_edges_of(model_->crease_points);
            const render::StrokeSource source{&gpu.cpu_mesh(), &gpu.cpu_fields(), &gpu.cpu_fine_normals(), &creases,
                                              gpu.feature_size()};
            render::write_vector_view(*renderer_, camera(), state_.settings, a.pixels.x, a.pixels.y, source,
                                      *vector_format, path);
            return report("wrote " + path);
        }
        // Without the panel: the drawing area, rendered as `kappa render` would.
        const Area a = drawing_area();
        const glm::ivec2 fb = window_->framebuffer_size();
        renderer_->set_interactive_hatching(false);  // as kappa render: the streamlines of this very view
        const render::Image image = with_panel ? read_window(fb.x, fb.y)
                                               : render::render_to_image(*renderer_, camera(), state_.settings,
                                                                         a.pixels.x, a.pixels.y);
        renderer_->set_interactive_hatching(true);
        render::write_image(path, image);
        report("wrote " + path);
    } catch (const std::exception& e) {
        report(e.what(), true);
    }
}

void ViewerApp::save_view(const std::string& path) {
    try {
        render::write_xf(path, orbit_.view());
        report("wrote " + path);
    } catch (const std::exception& e) {
        report(e.what(), true);
    }
}

void ViewerApp::load_view(const std::string& path) {
    try {
        orbit_.set_view(render::read_xf(path));
        if (renderer_ && renderer_->mesh()) orbit_.set_pivot(renderer_->mesh()->bounds().center);
        have_view_ = !model_;  // before the first mesh arrives: keep this view then
        report("read " + path);
    } catch (const std::exception& e) {
        report(e.what(), true);
    }
}

void ViewerApp::report(const std::string& message, bool error) {
    panel_.message = message;
    if (error) {
        std::fprintf(stderr, "kappa view: %s\n", message.c_str());
        if (options_.scripted()) exit_status_ = 1;
    }
    redraw_frames_ = 2;
}

}  // namespace kappa::viewer
