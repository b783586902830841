// The viewer's keyboard shortcuts: one table used by the key handler, the
// help window (F1 or ?), scripts (`key NAME`) and the README.
#pragma once

#include <string>
#include <vector>

namespace kappa::viewer {

enum class Action {
    ToggleLine, ToggleHiddenLines, CycleShading, ToggleLightFrame, CycleColorMap, ToggleColorBar,
    CycleHatching, ToggleFade, ToggleMsaa, WiderLines, ThinnerLines, RaiseThreshold, LowerThreshold,
    FitView, ResetView, TogglePanel, ToggleHelp, SaveScreenshot, SaveView, LoadView, Quit,
};

struct Shortcut {
    int key;          // GLFW_KEY_*
    int mods;         // GLFW_MOD_* that must be held (0: none)
    const char* name;  // as shown in help and written in scripts: "C", "Ctrl+S", "F1"
    Action action;
    const char* description;
    const char* line = nullptr;  // ToggleLine: the line kind (render::line_kinds())
    const char* setting = nullptr;  // the appearance setting it toggles or cycles (app/appearance_settings.h)
};

const std::vector<Shortcut>& shortcuts();

// The action for a key press, if any. Shift is ignored except where a
// shortcut needs it ('?' is Shift+/ on a US keyboard).
const Shortcut* find_shortcut(int key, int mods);
// By name, case-insensitive ("c", "ctrl+s", "?"); nullptr when unknown.
const Shortcut* find_shortcut(const std::string& name);
// The key that toggles a line kind ("C" for contours), nullptr when none does.
const Shortcut* find_line_shortcut(const std::string& line);
// The shortcut that toggles or cycles an appearance setting, if any.
const Shortcut* find_setting_shortcut(const std::string& setting);

}  // namespace kappa::viewer
