// Synthetic input for scripted viewer runs (`kappa view --script FILE`), so
// tests can orbit, pan, zoom, press shortcuts and change settings, then look
// at screenshots. One step a line; '#' starts a comment. Coordinates are
// window pixels (x right, y down from the top-left corner).
//
//   frames N                       draw N frames
//   drag X0 Y0 X1 Y1 [left|right|middle] [STEPS]
//                                  press, move in STEPS moves (default 8), one a
//                                  frame, release: left orbits, right or middle pans
//   scroll X Y CLICKS              mouse wheel at (X, Y): > 0 zooms in
//   key NAME                       a shortcut from the help window: C, Tab, Ctrl+S, ?
//   set NAME VALUE                 a `kappa render` option without dashes:
//                                  set lines contours   set shading none   set smooth-curvature 0.01
//   panel on|off                   show or hide the panel
//   wait-compute                   wait until background curvature has finished
//   wait-hatching                  wait until the streamline hatching of the view at
//                                  rest is drawn (the shader's strokes until then)
//   screenshot PATH [panel|no-panel]   (.svg or .pdf: the drawing area as vector strokes)
//                                  PNG of the whole window (default), or of the
//                                  drawing alone, as `kappa render` would write it
//   save-view PATH / load-view PATH  a trimesh2/rtsc .xf viewpoint
//   open PATH                      open another mesh (then wait-compute)
#pragma once

#include <glm/vec2.hpp>

#include <string>
#include <vector>

namespace kappa::viewer {

struct ScriptStep {
    enum Kind { Frames, Drag, Scroll, Key, Set, Panel, WaitCompute, WaitHatching, Screenshot, SaveView, LoadView, Open };
    Kind kind = Frames;
    int line = 0;          // in the script file, for messages
    int count = 1;         // frames; drag moves
    int button = 0;        // drag: 0 left, 1 right, 2 middle (GLFW numbering)
    glm::vec2 from{0}, to{0};  // drag; scroll position in `from`
    float amount = 0;      // scroll clicks
    bool flag = true;      // screenshot with the panel; panel on
    std::string name, value;  // key name; setting name and value; paths in `value`
};

// Parses a script; throws std::runtime_error "FILE:LINE: problem".
std::vector<ScriptStep> parse_script(const std::string& text, const std::string& file_name);
std::vector<ScriptStep> read_script(const std::string& path);

}  // namespace kappa::viewer
