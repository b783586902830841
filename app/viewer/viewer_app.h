// The interactive viewer behind `kappa view`: a GLFW window drawn by the same
// kappa::render::Renderer and RenderSettings as `kappa render`, a Dear ImGui
// panel, a trackball camera, curvature computed on a worker thread, and
// scripted runs (synthetic input, screenshots) for tests.
//
// Sources: viewer_app.cpp (window, frame loop, drawing), viewer_input.cpp
// (mouse, keys, shortcuts, file actions), viewer_script.cpp (scripted runs).
#pragma once

#include "app/viewer/background_compute.h"
#include "app/viewer/input_script.h"
#include "app/viewer/shortcuts.h"
#include "app/viewer/ui_panel.h"
#include "app/viewer/view_state.h"
#include "render/camera/orbit_camera.h"
#include "render/renderer.h"
#include "render/gl/window_context.h"

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace kappa::viewer {

struct ViewerOptions {
    std::string mesh_path;          // "" = the built-in model
    glm::ivec2 size{1280, 800};     // window size
    std::string xf_path;            // initial view (.xf), else framing from +z
    ViewState state;                // initial settings
    bool show_panel = true;
    // Scripted runs: the steps of --script, then `frames` frames and a
    // screenshot of the whole window to `screenshot`, then exit.
    std::vector<ScriptStep> script;
    int frames = 0;
    std::string screenshot;
    bool scripted() const { return frames > 0 || !script.empty(); }
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
};

class ViewerApp {
public:
    explicit ViewerApp(ViewerOptions options);
    ~ViewerApp();
    // Opens the window and runs until it is closed (or the script ends).
    // Returns the exit status; throws render::ContextError without a display.
    int run();

private:
    friend struct ViewerCallbacks;  // GLFW callbacks (viewer_input.cpp)

    // viewer_app.cpp
    void open_window();
    void wait_for_events();
    void draw_frame();
    void adopt_results();
    float effective_detail() const;  // the detail setting, 0 while explicit smoothing widths override it
    void show_model();                // the adopted model drawn, its first view's fields made here
    void request_first_view();        // ... or made by the worker (big meshes)
    void show_first_view(BackgroundCompute::ViewResult::First& first, const render::Camera& camera, int height);
    void mesh_uploaded(float window_s);
    // A big model's first view, sent a slice at a time (the frame's share timed from `since`).
    void continue_first_landing(std::chrono::steady_clock::time_point since);
    void request_view_fields();      // new detail fields when the view's scale changed
    void continue_field_upload(std::chrono::steady_clock::time_point since);
    bool send_slices(std::chrono::steady_clock::time_point since, const std::function<bool(size_t)>& send);
    bool view_fields_stale() const;  // the fields on the GPU are for another scale or direction of view
    // The drawing sits right of the panel: its left edge and size in window
    // coordinates (as the cursor), and its size in framebuffer pixels.
    struct Area {
        glm::vec2 origin{0}, size{1};
        glm::ivec2 pixels{1};
    };
    Area drawing_area() const;
    render::Camera camera() const;  // the view of the drawing area

    // viewer_input.cpp
    void install_callbacks();
    void mouse_button(int button, bool pressed, glm::vec2 at);
    void cursor_moved(glm::vec2 at);
    void scrolled(float clicks, glm::vec2 at);
    void apply(Action action, const char* line = nullptr);  // line: the kind ToggleLine toggles
    void open_mesh(const std::string& path);
    void save_screenshot(const std::string& path, bool with_panel);
    void save_view(const std::string& path);
    void load_view(const std::string& path);
    void report(const std::string& message, bool error = false);
    void handle_panel(const PanelRequests& requests);

    // viewer_script.cpp: advances the script by one frame; false when done.
    bool script_step();

    ViewerOptions options_;
    ViewState state_;
    PanelState panel_;
    std::unique_ptr<render::WindowContext> window_;
    std::unique_ptr<render::Renderer> renderer_;
    BackgroundCompute compute_;
    std::optional<Model> model_;
    render::OrbitCamera orbit_;
    bool have_view_ = false;  // the camera was set (a view file): keep it when the mesh arrives
    std::shared_ptr<const FaceClusters> face_clusters_;  // of the uploaded mesh, for view fields
    // The view the uploaded fields were computed for (detail 0: the raw fields).
    struct ShownFields {
        float detail = 0;
        render::Camera camera;
        int height = 0;
    } shown_;

    // Mouse drag in progress: GLFW button number, or -1.
    int drag_button_ = -1;
    glm::vec2 last_cursor_{0};
    int redraw_frames_ = 2;  // frames still to draw before waiting for events

    // Timing.
    std::deque<float> frame_ms_;  // the last frames, for the panel
    std::vector<float> still_ms_, moving_ms_;  // every frame with a model, reported after scripted runs
    std::vector<float> landing_ms_;  // the main thread's share of new fields in each frame, likewise
    bool full_quality_slow_ = false;  // the last full-quality frame took over 33 ms
    bool quick_frame_ = false;        // draw the next frame without MSAA (a big mesh just arrived)
    render::Camera last_view_;        // the last frame's view: another one means the view moves
    glm::ivec2 last_view_size_{0};
    float upload_s_ = 0, first_frame_s_ = 0;
    bool first_frame_drawn_ = false;
    bool first_view_pending_ = false;  // a big model's first view fields are on their way from the worker
    size_t frames_before_first_view_ = 0;  // drawn meanwhile (the first model's)
    // A big model's first view on its way to the GPU (MeshBuffers::InSlices), for the view
    // it was made for; the renderer gets it once the last slice is sent.
    std::unique_ptr<render::MeshBuffers> landing_;
    // A first view's buffer memory on a software GL, faulted in by the worker (app/heap_tuning.h).
    std::shared_ptr<app::HeapBlock> buffer_memory_;
    ShownFields landing_view_;
    size_t landing_slices_ = 0, landing_frames_ = 0;  // the first model's, reported with the first frame
    float landing_longest_ms_ = 0;                    // the window thread's longest share of a frame

    // Scripted runs.
    size_t step_ = 0;
    int frames_left_ = 0;  // of the current `frames` step
    int drag_moves_ = 0;   // of the current `drag` step
    bool final_frames_started_ = false;
    std::optional<ScriptStep> pending_screenshot_;  // taken at the end of the next frame
    int exit_status_ = 0;
};

}  // namespace kappa::viewer
