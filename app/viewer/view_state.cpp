#include "app/viewer/view_state.h"

#include "app/appearance_settings.h"
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

// The smoothing widths; the appearance settings come from
// app/appearance_settings.h, the table `kappa render` uses too.
const std::map<std::string, Setter>& setters() {
    static const std::map<std::string, Setter> table = [] {
        std::map<std::string, Setter> t = {
        {"smooth", {"auto or off", [](ViewState& s, const std::string& v) {
                        if (v != "auto" && v != "off") return false;
                        s.smoothing.automatic = v == "auto";
                        return true;
                    }}},
        {"estimator", {"one of " + cli::join(estimator_names(), ", "), [](ViewState& s, const std::string& v) {
                           const auto e = parse_estimator(v);
                           if (e) s.smoothing.estimator = *e;
                           return e.has_value();
                       }}},
        {"smooth-normals", number(0, 1e30f, [](ViewState& s) -> auto& { return s.smoothing.normals; })},
        {"smooth-curvature", number(0, 1e30f, [](ViewState& s) -> auto& { return s.smoothing.curvature; })},
        {"smooth-dcurv", number(0, 1e30f, [](ViewState& s) -> auto& { return s.smoothing.dcurv; })},
        };
        for (const app::AppearanceSetting& a : app::appearance_settings())
            t[a.name] = {a.expects, [&a](ViewState& s, const std::string& v) { return a.set(s.settings, v); }};
        return t;
    }();
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
