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
};

const std::vector<AppearanceSetting>& appearance_settings();
const AppearanceSetting* find_appearance_setting(const std::string& name);

}  // namespace kappa::app
