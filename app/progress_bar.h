// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <string>

namespace kappa::app {

class ProgressBar {
public:
    explicit ProgressBar(bool wanted);
    void update(float fraction, const char* stage);
    void finish();  // clears the line

private:
    bool active_;
    int last_percent_ = -1;
};

}  // namespace kappa::app
