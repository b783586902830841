#include "app/viewer/shortcuts.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>

namespace kappa::viewer {

const std::vector<Shortcut>& shortcuts() {
    static const std::vector<Shortcut> table = {
        {GLFW_KEY_C, 0, "C", Action::ToggleLine, "occluding contours on/off", "contours"},
        {GLFW_KEY_E, 0, "E", Action::ToggleLine, "exterior silhouette on/off", "silhouette"},
        {GLFW_KEY_S, 0, "S", Action::ToggleLine, "suggestive contours on/off", "suggestive"},
        {GLFW_KEY_F, GLFW_MOD_CONTROL, "Ctrl+F", Action::ToggleLine, "suggestive highlights on/off",
         "suggestive-highlights"},
        {GLFW_KEY_W, 0, "W", Action::ToggleLine, "Dw kr = threshold lines on/off", "dwkr"},
        {GLFW_KEY_B, 0, "B", Action::ToggleLine, "boundary lines on/off", "boundaries"},
        {GLFW_KEY_R, GLFW_MOD_CONTROL, "Ctrl+R", Action::ToggleLine, "ridges on/off", "ridges"},
        {GLFW_KEY_V, GLFW_MOD_CONTROL, "Ctrl+V", Action::ToggleLine, "valleys on/off", "valleys"},
        {GLFW_KEY_A, GLFW_MOD_CONTROL, "Ctrl+A", Action::ToggleLine, "apparent ridges on/off", "apparent-ridges"},
        {GLFW_KEY_P, GLFW_MOD_CONTROL, "Ctrl+P", Action::ToggleLine, "principal highlights on/off",
         "principal-highlights"},
        {GLFW_KEY_K, GLFW_MOD_CONTROL, "Ctrl+K", Action::ToggleLine, "parabolic lines (K = 0) on/off", "parabolic"},
        {GLFW_KEY_H, GLFW_MOD_CONTROL, "Ctrl+H", Action::ToggleLine, "H = 0 lines on/off", "mean-zero"},
        {GLFW_KEY_I, 0, "I", Action::ToggleLine, "isophotes on/off", "isophotes"},
        {GLFW_KEY_T, 0, "T", Action::ToggleLine, "topographic lines on/off", "topo"},
        {GLFW_KEY_D, 0, "D", Action::ToggleHiddenLines, "hidden lines (dashed) on/off", nullptr, "hidden-lines"},
        {GLFW_KEY_L, 0, "L", Action::CycleShading, "next shading: none, lambert, toon, hemisphere, toon-bw, gooch", nullptr, "shading"},
        {GLFW_KEY_L, GLFW_MOD_CONTROL, "Ctrl+L", Action::ToggleLightFrame, "light fixed to the camera or the model", nullptr, "light-frame"},
        {GLFW_KEY_M, 0, "M", Action::CycleColorMap, "next curvature colour map", nullptr, "colormap"},
        {GLFW_KEY_K, 0, "K", Action::ToggleColorBar, "colour bar on/off", nullptr, "colorbar"},
        {GLFW_KEY_H, 0, "H", Action::CycleHatching, "next hatching: none, min, max, cross", nullptr, "hatching"},
        {GLFW_KEY_G, 0, "G", Action::ToggleFade, "fading of weak lines on/off", nullptr, "fade"},
        {GLFW_KEY_A, 0, "A", Action::ToggleMsaa, "4x multisampling on/off", nullptr, "msaa"},
        {GLFW_KEY_EQUAL, 0, "=", Action::WiderLines, "wider lines"},
        {GLFW_KEY_MINUS, 0, "-", Action::ThinnerLines, "thinner lines"},
        {GLFW_KEY_RIGHT_BRACKET, 0, "]", Action::RaiseThreshold, "raise the suggestive-contour threshold"},
        {GLFW_KEY_LEFT_BRACKET, 0, "[", Action::LowerThreshold, "lower the suggestive-contour threshold"},
        {GLFW_KEY_F, 0, "F", Action::FitView, "fit the model to the window"},
        {GLFW_KEY_R, 0, "R", Action::ResetView, "reset the view (the default three-quarter view)"},
        {GLFW_KEY_TAB, 0, "Tab", Action::TogglePanel, "show/hide the panel"},
        {GLFW_KEY_F1, 0, "F1", Action::ToggleHelp, "this help"},
        {GLFW_KEY_SLASH, GLFW_MOD_SHIFT, "?", Action::ToggleHelp, "this help"},
        {GLFW_KEY_P, 0, "P", Action::SaveScreenshot, "save a screenshot (path in the Files section)"},
        {GLFW_KEY_S, GLFW_MOD_CONTROL, "Ctrl+S", Action::SaveView, "save the view to the .xf file"},
        {GLFW_KEY_O, GLFW_MOD_CONTROL, "Ctrl+O", Action::LoadView, "load the view from the .xf file"},
        {GLFW_KEY_Q, GLFW_MOD_CONTROL, "Ctrl+Q", Action::Quit, "quit"},
    };
    return table;
}

const Shortcut* find_shortcut(int key, int mods) {
    const int relevant = mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER);
    for (const auto& s : shortcuts()) {
        if (s.key != key) continue;
        if (s.mods & GLFW_MOD_SHIFT) {
            if ((mods & GLFW_MOD_SHIFT) && relevant == 0) return &s;
        } else if (relevant == s.mods) {
            return &s;
        }
    }
    return nullptr;
}

const Shortcut* find_shortcut(const std::string& name) {
    auto lower = [](std::string s) {
        std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        return s;
    };
    for (const auto& s : shortcuts())
        if (lower(s.name) == lower(name)) return &s;
    return nullptr;
}

const Shortcut* find_setting_shortcut(const std::string& setting) {
    for (const auto& s : shortcuts())
        if (s.setting && setting == s.setting) return &s;
    return nullptr;
}

const Shortcut* find_line_shortcut(const std::string& line) {
    for (const auto& s : shortcuts())
        if (s.line && line == s.line) return &s;
    return nullptr;
}

}  // namespace kappa::viewer
