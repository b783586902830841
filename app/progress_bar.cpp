#include "progress_bar.h"

#include <cstdio>
#include <unistd.h>

namespace kappa::app {

ProgressBar::ProgressBar(bool wanted) : active_(wanted && isatty(fileno(stderr))) {}

void ProgressBar::update(float fraction, const char* stage) {
    if (!active_) return;
    const int percent = int(fraction * 100.0f + 0.5f);
    if (percent == last_percent_) return;
    last_percent_ = percent;
    const int width = 30, filled = percent * width / 100;
    std::fprintf(stderr, "\r[%.*s%*s] %3d%% %-28s", filled, "##############################", width - filled, "",
                 percent, stage);
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (!active_) return;
    std::fprintf(stderr, "\r%*s\r", 72, "");
    std::fflush(stderr);
}

}  // namespace kappa::app
