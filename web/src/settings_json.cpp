#include "web/src/settings_json.h"

#include "app/appearance_settings.h"

#include <cstdio>

namespace kappa::web {

namespace {

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\', out += c;
        else if (c == '\n') out += "\\n";
        else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
        else out += c;
    }
    return out + "\"";
}

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", x);
    return text;
}

std::string hex_color(glm::vec3 c) {
    char text[8];
    auto byte = [](float x) { return int(x <= 0 ? 0 : x >= 1 ? 255 : x * 255.0f + 0.5f); };
    std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return text;
}

// The setting's kind and current value as the panel shows them.
std::string setting_entry(const app::AppearanceSetting& a, const render::RenderSettings& s) {
    std::string kind = "text", value = "\"\"";
    if (!a.choices.empty() && a.get) kind = "choice", value = quoted(a.get(s));
    else if (a.flag) kind = "choice", value = quoted(s.*a.flag ? "on" : "off");
    else if (a.number) kind = "number", value = number(s.*a.number);
    else if (a.integer) kind = "integer", value = number(s.*a.integer);
    else if (a.vec3 && a.color) kind = "color", value = quoted(hex_color(s.*a.vec3));
    else if (a.vec4 && a.color) kind = "color", value = quoted(hex_color(glm::vec3(s.*a.vec4)));
    else if (a.vec3) {
        const glm::vec3 v = s.*a.vec3;
        kind = "vector", value = quoted(number(v.x) + "," + number(v.y) + "," + number(v.z));
    } else if (a.get) value = quoted(a.get(s));
    std::string choices = a.flag && a.choices.empty() ? "\"off\",\"on\"" : "";
    for (const std::string& c : a.choices) choices += (choices.empty() ? "" : ",") + quoted(c);
    return "{\"name\":" + quoted(a.name) + ",\"label\":" + quoted(a.label.empty() ? a.name : a.label) +
           ",\"help\":" + quoted(a.help) + ",\"expects\":" + quoted(a.expects) + ",\"kind\":" + quoted(kind) +
           ",\"value\":" + value + ",\"min\":" + number(a.slider_min) + ",\"max\":" + number(a.slider_max) +
           ",\"log\":" + (a.logarithmic ? "true" : "false") + ",\"can_be_off\":" + (a.can_be_off ? "true" : "false") +
           ",\"choices\":[" + choices + "]}";
}

}  // namespace

std::string settings_json(const render::RenderSettings& s) {
    std::string out = "{\"settings\":[";
    bool first = true;
    for (const app::AppearanceSetting& a : app::appearance_settings()) {
        out += (first ? "" : ",") + setting_entry(a, s);
        first = false;
    }
    out += "],\"lines\":[";
    first = true;
    for (const app::LineGroup& g : app::line_groups()) {
        out += std::string(first ? "" : ",") + "{\"title\":" + quoted(g.title) + ",\"lines\":[";
        first = false;
        bool first_line = true;
        for (const app::LineToggle& t : g.lines) {
            const render::LineKind* kind = render::find_line_kind(t.kind);
            const bool on = kind && s.lines.*(kind->flag);
            out += std::string(first_line ? "" : ",") + "{\"kind\":" + quoted(t.kind) +
                   ",\"label\":" + quoted(t.label) +
                   ",\"setting\":" + quoted(t.setting) + ",\"on\":" + (on ? "true" : "false") + "}";
            first_line = false;
        }
        out += "]}";
    }
    return out + "]}";
}

}  // namespace kappa::web
