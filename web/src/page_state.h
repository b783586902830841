// What the page shows: one mesh prepared for drawing (app/mesh_drawing.h, as
// `kappa render` prepares it), the settings of app/appearance_settings.h, the
// orbit camera of the desktop viewer, and the WebGL2 context that draws into
// the page's canvas. The page's JavaScript (web/page/kappa-page.js) drives it
// through the functions of page_api.cpp.
#pragma once

#include "app/mesh_drawing.h"
#include "app/render_options.h"
#include "render/camera/orbit_camera.h"
#include "render/renderer.h"

#include <emscripten/html5.h>

#include <memory>
#include <optional>
#include <string>

namespace kappa::web {

class PageState {
public:
    // Creates the WebGL2 context of the canvas (CSS selector) and the renderer;
    // throws std::runtime_error with a one-line reason.
    void start(const std::string& canvas);
    // Reads `path` (in the page's in-memory file system) and prepares it;
    // the view goes back to the requested one. Throws "PATH: problem".
    void open(const std::string& path);
    // An appearance setting by its command-line name; throws cli's one-line message on a bad value.
    void set(const std::string& name, const std::string& value);
    // The view --view AZ,EL would give (nullopt: the default view), from now and for each next mesh.
    void set_view(std::optional<ViewAngles> angles);
    void resize(int width, int height);
    // While the view moves, frames keep the fields they have; at rest the
    // fields of the view are prepared (with --detail they follow the zoom),
    // in slices: prepare works on them for about `seconds` and returns true
    // once they are uploaded (app/mesh_drawing.h's prepare_view_slice).
    void set_moving(bool moving) { moving_ = moving; }
    bool prepare(double seconds);
    bool view_prepared() const {
        return !drawing_ || (drawing_->opened() && drawing_->view_prepared(camera(), size_));
    }
    render::OrbitCamera& orbit() { return orbit_; }
    glm::ivec2 size() const { return size_; }
    bool has_mesh() const { return drawing_ != nullptr; }

    // Draws the current view into the canvas, with the fields prepared so far
    // (a new mesh: the background until its first fields are uploaded).
    void draw();
    // Writes the current view to `path`: .svg (the CLI's writer) or .png.
    void write(const std::string& path);
    const render::RenderSettings& settings() const { return options_.settings; }

private:
    void prepare();     // the MeshDrawing of input_ with the current settings, to open in steps
    app::MeshDrawing& open_drawing();  // drawing_, opened now if it is not yet
    bool open_step();                  // drawing_'s next step (MeshDrawing::open_step)
    void reset_view();  // the requested view of the mesh
    render::Camera camera() const { return {orbit_.view(), fov_}; }

    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context_ = 0;
    std::unique_ptr<render::Renderer> renderer_;
    app::RenderOptions options_;
    std::optional<Mesh> input_;  // kept to prepare again when the crease angle or detail changes
    std::string path_;
    std::unique_ptr<app::MeshDrawing> drawing_;
    render::OrbitCamera orbit_;
    float fov_ = 30;
    glm::ivec2 size_{800, 600};
    bool moving_ = false;
    bool shown_ = false;  // the renderer holds fields of drawing_'s mesh
    bool view_reset_ = false;  // the requested view is to be set once drawing_ is open
};

}  // namespace kappa::web
