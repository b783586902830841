#include "app/viewer/view_state.h"

#include "app/cli_options.h"

#include <cstdio>
#include <functional>
#include <map>

namespace kappa::viewer {

namespace {

using render::RenderSettings;

struct Setter {
    std::string expects;
    std::function<bool(ViewState&, const std::string&)> set;
};

std::optional<bool> parse_on_off(const std::string& v) {
    if (v == "on") return true;
    if (v == "off") return false;
    return std::nullopt;
}

// A number in [lo, hi] into `field` of the state.
Setter number(float lo, float hi, std::function<float&(ViewState&)> field) {
    char expects[64];
    std::snprintf(expects, sizeof expects, hi > 1e5f ? "a number >= %g" : "a number in [%g, %g]", lo, hi);
    return {expects, [=](ViewState& s, const std::string& v) {
                auto x = cli::parse_number(v);
                if (!x || *x < lo || *x > hi) return false;
                field(s) = float(*x);
                return true;
            }};
}

Setter on_off(std::function<bool&(ViewState&)> field) {
    return {"on or off", [=](ViewState& s, const std::string& v) {
                auto b = parse_on_off(v);
                if (b) field(s) = *b;
                return bool(b);
            }};
}

template <typename T>
Setter word(const std::string& expects, std::optional<T> (*parse)(const std::string&),
            std::function<T&(ViewState&)> field) {
    return {expects, [=](ViewState& s, const std::string& v) {
                auto e = parse(v);
                if (e) field(s) = *e;
                return bool(e);
            }};
}

const std::map<std::string, Setter>& setters() {
    static const std::map<std::string, Setter> table = {
        {"lines", word<render::LineSelection>("a comma list of contours, suggestive, boundaries, or none",
                                              render::parse_lines, [](ViewState& s) -> auto& { return s.settings.lines; })},
        {"shading", word<render::Shading>("one of " + cli::join(render::shading_names(), ", "), render::parse_shading,
                                          [](ViewState& s) -> auto& { return s.settings.shading; })},
        {"colormap", word<render::ColorMap>("one of " + cli::join(render::colormap_names(), ", "),
                                            render::parse_colormap, [](ViewState& s) -> auto& { return s.settings.colormap; })},
        {"hatching", word<render::Hatching>("one of " + cli::join(render::hatching_names(), ", "),
                                            render::parse_hatching, [](ViewState& s) -> auto& { return s.settings.hatching; })},
        {"background", word<glm::vec4>("white, transparent, black or #rrggbb", render::parse_background,
                                       [](ViewState& s) -> auto& { return s.settings.background; })},
        {"light", {"X,Y,Z", [](ViewState& s, const std::string& v) {
                       auto d = cli::parse_vec3(v);
                       if (d) s.settings.light_dir = *d;
                       return bool(d);
                   }}},
        {"detail", word<float>("a size in pixels (0 < PX <= 1000) or off", render::parse_detail,
                               [](ViewState& s) -> auto& { return s.settings.detail; })},
        {"crease-angle", word<float>("auto, off, or degrees in [0, 180)", render::parse_crease_angle,
                                     [](ViewState& s) -> auto& { return s.settings.crease_angle; })},
        {"colorbar", on_off([](ViewState& s) -> auto& { return s.settings.colorbar; })},
        {"fade", on_off([](ViewState& s) -> auto& { return s.settings.fade; })},
        {"msaa", on_off([](ViewState& s) -> auto& { return s.settings.msaa; })},
        {"hatch-spacing", number(2, 100, [](ViewState& s) -> auto& { return s.settings.hatch_spacing; })},
        {"sc-threshold", number(0, 1e6f, [](ViewState& s) -> auto& { return s.settings.sc_threshold; })},
        {"line-width", number(0.1f, 64, [](ViewState& s) -> auto& { return s.settings.line_width; })},
        {"smooth", {"auto or off", [](ViewState& s, const std::string& v) {
                        if (v != "auto" && v != "off") return false;
                        s.smoothing.automatic = v == "auto";
                        return true;
                    }}},
        {"smooth-normals", number(0, 1e30f, [](ViewState& s) -> auto& { return s.smoothing.normals; })},
        {"smooth-curvature", number(0, 1e30f, [](ViewState& s) -> auto& { return s.smoothing.curvature; })},
        {"smooth-dcurv", number(0, 1e30f, [](ViewState& s) -> auto& { return s.smoothing.dcurv; })},
    };
    return table;
}

}  // namespace

const std::vector<std::string>& setting_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const auto& [name, setter] : setters()) n.push_back(name);
        return n;
    }();
    return names;
}

std::optional<std::string> assign_setting(ViewState& state, const std::string& name, const std::string& value) {
    const auto it = setters().find(name);
    if (it == setters().end()) {
        const std::string guess = cli::closest_match(name, setting_names());
        return "unknown setting '" + name + "'" + (guess.empty() ? "" : "; did you mean '" + guess + "'?");
    }
    if (!it->second.set(state, value)) return "--" + name + " expects " + it->second.expects + ", got '" + value + "'";
    return std::nullopt;
}

}  // namespace kappa::viewer
