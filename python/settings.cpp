// kappa.settings and kappa.line_groups: the table of appearance settings
// (app/appearance_settings.h) for the module's users that build their own
// panels (the Blender add-on, blender/kappa_lines): names, help, ranges and
// defaults, so nothing is typed twice.
#include "bindings.h"

#include "app/appearance_settings.h"

#include <pybind11/stl.h>

#include <cstdio>
#include <cstdlib>

namespace kappa::python {

namespace {

std::string keyword(std::string name) {
    for (char& c : name)
        if (c == '-') c = '_';
    return name;
}

// A float32 setting as the decimal it was written as (0.05, not 0.05000000074505806).
double decimal(float x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", double(x));
    return std::strtod(text, nullptr);
}

// What a panel draws for the setting, and its default in kappa's own terms.
void describe(py::dict& out, const app::AppearanceSetting& a, const render::RenderSettings& d) {
    if (a.name == "lines") {
        py::list on;
        for (const render::LineKind& k : render::line_kinds())
            if (d.lines.*k.flag) on.append(k.name);
        out["kind"] = "lines", out["default"] = on, out["choices"] = render::line_names();
    } else if (a.number) {
        out["kind"] = "number", out["default"] = decimal(d.*a.number);
    } else if (a.integer) {
        out["kind"] = "integer", out["default"] = d.*a.integer;
    } else if (a.vec4 || a.vec3) {
        const glm::vec4 v = a.vec4 ? d.*a.vec4 : glm::vec4(d.*a.vec3, 1.0f);
        out["kind"] = a.color ? "color" : "vector";
        out["default"] = a.vec4 ? py::make_tuple(decimal(v.x), decimal(v.y), decimal(v.z), decimal(v.w))
                                : py::make_tuple(decimal(v.x), decimal(v.y), decimal(v.z));
    } else if (a.get && (a.choices == std::vector<std::string>{"off", "on"} || a.expects == "on or off")) {
        out["kind"] = "switch", out["default"] = a.get(d) == "on";
    } else if (a.get) {
        out["kind"] = "choice", out["default"] = a.get(d), out["choices"] = a.choices;
    } else {
        out["kind"] = "text", out["default"] = py::none();
    }
    if (a.number || a.integer) {
        out["min"] = decimal(a.slider_min), out["max"] = decimal(a.slider_max);
        out["logarithmic"] = a.logarithmic, out["can_be_off"] = a.can_be_off;
    } else if (a.vec3 && !a.color) {
        out["min"] = decimal(a.slider_min), out["max"] = decimal(a.slider_max);
    }
}

}  // namespace

void def_settings(py::module_& m) {
    m.def(
        "settings",
        [] {
            const render::RenderSettings defaults;
            py::list out;
            for (const app::AppearanceSetting& a : app::appearance_settings()) {
                py::dict s;
                s["name"] = keyword(a.name);
                s["label"] = a.label.empty() ? a.name : a.label;
                s["help"] = a.help;
                s["expects"] = a.expects;
                describe(s, a, defaults);
                out.append(s);
            }
            return out;
        },
        R"(kappa's appearance settings (the keywords of render/strokes/write), in the order of `kappa render --help`:
a list of dicts with name ('line_width'), label, help (with the default), expects (the accepted values,
for messages), kind ('number', 'integer', 'switch', 'choice', 'lines', 'color', 'vector' or 'text') and
default; numbers and integers also have min and max (the panel's slider; `expects` may allow more),
logarithmic and can_be_off (0 means off); choices and lines have choices.)");
    m.def(
        "line_groups",
        [] {
            py::list out;
            for (const app::LineGroup& g : app::line_groups()) {
                py::list lines;
                for (const app::LineToggle& t : g.lines) {
                    py::dict line;
                    line["kind"] = t.kind, line["label"] = t.label, line["setting"] = keyword(t.setting);
                    lines.append(line);
                }
                py::dict group;
                group["title"] = g.title, group["lines"] = lines;
                out.append(group);
            }
            return out;
        },
        R"(The line kinds of the lines setting in the groups kappa's panel shows: a list of {'title', 'lines': [{'kind':
'apparent-ridges', 'label': 'apparent ridges', 'setting': the keyword of its threshold or count ('' if none)}]}.)");
}

}  // namespace kappa::python
