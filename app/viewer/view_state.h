// What the viewer's panel, shortcuts and scripts edit: the very settings
// structure `kappa render` uses, plus the curvature smoothing widths.
#pragma once

#include "geometry/surface_analysis.h"
#include "render/render_settings.h"

#include <optional>
#include <string>
#include <vector>

namespace kappa::viewer {

struct ViewState {
    render::RenderSettings settings;
    SmoothingOptions smoothing;
};

// The names `kappa render` gives these settings on its command line, without
// the dashes: lines, shading, light, colormap, colorbar, hatching,
// hatch-spacing, sc-threshold, line-width, fade, background, msaa,
// estimator, smooth-normals, smooth-curvature, smooth-dcurv.
const std::vector<std::string>& setting_names();

// Sets one of them from its command-line text ("lines" "contours,boundaries",
// "fade" "off", "light" "0,1,1", "colorbar" "on"). Returns an error message
// ("--fade expects on or off, got 'x'"), or nullopt when it was set.
std::optional<std::string> assign_setting(ViewState& state, const std::string& name, const std::string& value);

}  // namespace kappa::viewer
