// Every appearance setting of render::RenderSettings declared once: its name
// (the command-line option without dashes, and the name of the viewer
// script's `set`), what it takes, its help (with the default) and how text
// sets it. `kappa render` and `kappa view` build their options from this
// table, the viewer's scripts assign through it, and the help texts are the
// same everywhere.
#pragma once

#include "render/render_settings.h"

#include <functional>
#include <string>
#include <vector>

namespace kappa::app {

struct AppearanceSetting {
    std::string name;     // "line-width"
    std::string metavar;  // "PX"
    std::string help;     // one sentence, with the default
    std::string expects;  // for errors: "a number in [0.1, 64]"
    // Sets the field from text; false when the text is not a valid value.
    std::function<bool(render::RenderSettings&, const std::string&)> set;
    // On the command line a flag without value (--colorbar); in scripts on|off.
    bool render::RenderSettings::*flag = nullptr;

    // The viewer's panel (app/viewer/ui_panel.cpp) draws each setting from
    // the fields below: numbers as a slider over [slider_min, slider_max]
    // (the command line accepts the wider range of `expects`), vectors and
    // colours, and words (below); lists (lines, vectors) have their groups.
    float render::RenderSettings::*number = nullptr;
    int render::RenderSettings::*integer = nullptr;
    float slider_min = 0, slider_max = 0;
    bool logarithmic = false;
    const char* format = "%.3f";
    bool can_be_off = false;  // a number whose 0 means off: a checkbox beside its slider
    // Vectors: three sliders over [slider_min, slider_max], or a colour
    // picker when `color` (vec4: with its opacity).
    glm::vec3 render::RenderSettings::*vec3 = nullptr;
    glm::vec4 render::RenderSettings::*vec4 = nullptr;
    bool color = false;
    // Settings that take one of a few words are drawn from these: `choices`
    // as a combo box, or as a checkbox when they are exactly off and on;
    // `get` gives the current word, `set` takes the one picked.
    std::vector<std::string> choices{};
    std::function<std::string(const render::RenderSettings&)> get{};
    std::string label{};  // in the panel (empty: the name)
};

const std::vector<AppearanceSetting>& appearance_settings();
const AppearanceSetting* find_appearance_setting(const std::string& name);

// The line kinds of --lines as the panel shows them: in groups, each with
// its label and the setting of its threshold or count (empty: none).
struct LineToggle {
    std::string kind;     // render::line_kinds() name
    std::string label;    // "apparent ridges"
    std::string setting;  // "ar-threshold"
};
struct LineGroup {
    std::string title;
    std::vector<LineToggle> lines;
};
const std::vector<LineGroup>& line_groups();

}  // namespace kappa::app
