// Reading the window back for screenshots.
#pragma once

#include "render/image/image.h"

namespace kappa::viewer {

// The window's back buffer (what the next swap will show: drawing and
// panel) as an opaque RGBA image, top row first.
render::Image read_window(int width, int height);

}  // namespace kappa::viewer
