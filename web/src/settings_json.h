// The settings table (app/appearance_settings.h) and the line groups of the
// desktop viewer's panel as JSON, with the current values: the page builds
// its panel from it (web/page/kappa-page.js), so each setting is declared once.
#pragma once

#include "render/render_settings.h"

#include <string>

namespace kappa::web {

// {"settings": [{"name", "label", "help", "expects", "kind", "value", "min", "max", "log", "choices"}...],
//  "lines": [{"title", "lines": [{"kind", "label", "setting", "on"}...]}...]}
// kind: "choice", "number", "integer", "color", "vector" or "text" (set by its command-line words).
std::string settings_json(const render::RenderSettings& settings);

}  // namespace kappa::web
