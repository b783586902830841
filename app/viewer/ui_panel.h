// The viewer's Dear ImGui panel: every setting of `kappa render` (editing the
// shared RenderSettings), curvature smoothing widths, the mesh's statistics
// and timings, and file actions (open, screenshot, .xf view). Also the help
// window and the progress bar shown while curvature is being computed.
#pragma once

#include "app/viewer/background_compute.h"
#include "app/viewer/view_state.h"

#include <string>

namespace kappa::viewer {

// What the panel remembers between frames.
struct PanelState {
    bool visible = true;
    bool help = false;
    std::string open_path;
    std::string screenshot_path = "kappa-view.png";
    bool screenshot_with_panel = true;
    bool fast_while_moving = true;  // no MSAA while dragging when frames are slow
    std::string view_path = "kappa-view.xf";
    std::string message;  // the outcome of the last action ("wrote ...", an error)
};

// What the viewer shows but the panel does not own.
struct PanelInfo {
    const Model* model = nullptr;  // nullptr while the first mesh loads
    float map_range = 1;           // of the current colour map, from the renderer
    float upload_s = 0, first_frame_s = 0;
    bool computing = false;
    float progress = 0;  // of the worker's job, in [0, 1]; negative: not known (a first view's fields)
    std::string stage;
    float frame_ms = 0;    // median of recent frames
    std::string gl;        // renderer description
};

// Buttons pressed this frame.
struct PanelRequests {
    bool open = false, screenshot = false, save_view = false, load_view = false, fit = false, reset = false;
    bool recompute = false;  // a smoothing width was changed (on release of its slider)
};

// Width of the panel at the left edge, in window coordinates.
float panel_width(float ui_scale);
// Draws the panel at the left edge.
PanelRequests draw_panel(ViewState& state, PanelState& panel, const PanelInfo& info, float ui_scale);
void draw_help_window(bool* open, float ui_scale);
// A small progress box at the bottom of the window while curvature runs.
void draw_progress_overlay(const PanelInfo& info, float ui_scale);

}  // namespace kappa::viewer
