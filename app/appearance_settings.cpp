#include "app/appearance_settings.h"

#include "app/cli_options.h"

#include <cmath>
#include <optional>
#include <cstdio>

namespace kappa::app {

namespace {

using render::RenderSettings;
using Set = std::function<bool(RenderSettings&, const std::string&)>;

std::string range_text(float lo, float hi) {
    char text[64];
    std::snprintf(text, sizeof text, hi > 1e5f ? "a number >= %g" : "a number in [%g, %g]", double(lo), double(hi));
    return text;
}

// A number in [lo, hi] into the field.
Set number(float lo, float hi, float RenderSettings::*field) {
    return [=](RenderSettings& s, const std::string& v) {
        auto x = cli::parse_number(v);
        if (!x || *x < lo || *x > hi) return false;
        s.*field = float(*x);
        return true;
    };
}

// An integer in [lo, hi] into the field.
Set integer(int lo, int hi, int RenderSettings::*field) {
    return [=](RenderSettings& s, const std::string& v) {
        auto x = cli::parse_number(v);
        if (!x || *x != std::floor(*x) || *x < lo || *x > hi) return false;
        s.*field = int(*x);
        return true;
    };
}

Set on_off(bool RenderSettings::*field) {
    return [=](RenderSettings& s, const std::string& v) {
        if (v != "on" && v != "off") return false;
        s.*field = v == "on";
        return true;
    };
}

template <typename T>
Set word(std::optional<T> (*parse)(const std::string&), T RenderSettings::*field) {
    return [=](RenderSettings& s, const std::string& v) {
        auto e = parse(v);
        if (e) s.*field = *e;
        return bool(e);
    };
}

std::string one_of(const std::vector<std::string>& names) { return "one of " + cli::join(names, ", "); }

// A number in [lo, hi] on the command line, a slider over [slider_min, slider_max] in the panel.
AppearanceSetting real(std::string name, std::string metavar, std::string help, float lo, float hi,
                       float RenderSettings::*field, float slider_min, float slider_max, bool logarithmic,
                       const char* format = "%.3f") {
    AppearanceSetting a{std::move(name), std::move(metavar), std::move(help), range_text(lo, hi), number(lo, hi, field)};
    a.number = field;
    a.slider_min = slider_min;
    a.slider_max = slider_max;
    a.logarithmic = logarithmic;
    a.format = format;
    return a;
}

AppearanceSetting count(std::string name, std::string help, int lo, int hi, int RenderSettings::*field,
                        int slider_max) {
    AppearanceSetting a{std::move(name), "N", std::move(help),
                        "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
                        integer(lo, hi, field)};
    a.integer = field;
    a.slider_min = float(lo);
    a.slider_max = float(slider_max);
    return a;
}

// On or off, as a checkbox in the panel; cli_flag: on the command line a
// flag without value (--colorbar) instead of --NAME on|off.
AppearanceSetting switch_setting(std::string name, std::string help, bool RenderSettings::*field, std::string label,
                                 bool cli_flag = false) {
    AppearanceSetting a{std::move(name), "on|off", std::move(help), "on or off", on_off(field),
                        cli_flag ? field : nullptr};
    a.choices = {"off", "on"};
    a.get = [=](const RenderSettings& s) { return std::string(s.*field ? "on" : "off"); };
    a.label = std::move(label);
    return a;
}

// On or off for vector output: not in the viewer's panel (no choices), its
// value readable (get: kappa.settings() gives the default).
AppearanceSetting output_switch(std::string name, std::string help, bool RenderSettings::*field, bool cli_flag = false) {
    AppearanceSetting a{std::move(name), "on|off", std::move(help), "on or off", on_off(field),
                        cli_flag ? field : nullptr};
    a.get = [=](const RenderSettings& s) { return std::string(s.*field ? "on" : "off"); };
    return a;
}

// One of the names of an enum (render_settings.h), as a combo box in the panel.
template <typename T>
AppearanceSetting choice_setting(std::string name, const std::vector<std::string>& names, std::string help,
                                 std::optional<T> (*parse)(const std::string&), T RenderSettings::*field,
                                 std::string label) {
    AppearanceSetting a{std::move(name), cli::join(names, "|"), std::move(help), one_of(names), word(parse, field)};
    a.choices = names;
    a.get = [=](const RenderSettings& s) { return names[size_t(s.*field)]; };
    a.label = std::move(label);
    return a;
}

}  // namespace

const std::vector<AppearanceSetting>& appearance_settings() {
    using R = RenderSettings;
    static const std::vector<AppearanceSetting> table = {
        {"lines", "LIST",
         "lines to draw, comma list of: contours, suggestive, boundaries, creases, ridges, valleys, parabolic, "
         "mean-zero, isophotes, topo, silhouette (exterior contours only), apparent-ridges, suggestive-highlights, "
         "principal-highlights, dwkr (Dw kr = the suggestive-contour threshold), none (default "
         "contours,suggestive,creases)",
         "a comma list of " + cli::join(render::line_names(), ", "), word(render::parse_lines, &R::lines)},
        [] {
            AppearanceSetting a{"detail", "PX|off",
                                "scale of the surface the lines follow, in pixels on screen: shape features much "
                                "smaller draw no lines (default 12; off: the paper's raw 1-ring estimate)",
                                "a size in pixels (0 < PX <= 1000) or off", word(render::parse_detail, &R::detail)};
            a.number = &R::detail, a.slider_min = 1, a.slider_max = 64, a.logarithmic = true, a.format = "%.1f px";
            a.can_be_off = true;
            return a;
        }(),
        {"crease-angle", "DEG|auto|off",
         "sharp edges: where faces turn by more than DEG degrees the mesh is split (normals and curvature per "
         "side) and the edge drawn as a crease; auto (default): 40 on meshes made of flat and sharp pieces, off on "
         "smooth ones",
         "auto, off, or degrees in [0, 180)", word(render::parse_crease_angle, &R::crease_angle)},
        real("sc-threshold", "S",
             "suggestive-contour threshold s, dimensionless: drawn where Dw kr > s / fs^2; also the value of the "
             "dwkr lines (default 0.05)",
             0, 1e6f, &R::sc_threshold, 0, 2, true),
        real("rv-threshold", "S",
             "ridges and valleys where the larger principal curvature |kmax| > S / fs, dimensionless (default 1.5)", 0,
             1e6f, &R::rv_threshold, 0, 10, true, "%.2f"),
        real("ar-threshold", "S",
             "apparent ridges where the view-dependent curvature > S / fs, dimensionless (default 1)", 0, 1e6f,
             &R::ar_threshold, 0, 10, true, "%.2f"),
        real("sh-threshold", "S", "suggestive highlights where -Dw kr > S / fs^2, dimensionless (default 0.1)", 0,
             1e6f, &R::sh_threshold, 0, 2, true),
        real("ph-threshold", "S",
             "principal highlights where (kmax^2 - kmin^2) n.v > S / fs^2, kmax the curvature of larger magnitude, "
             "dimensionless (default 0.2)",
             0, 1e6f, &R::ph_threshold, 0, 4, true),
        count("isophotes", "number of isophotes (lines of n.l = (k - 1/2) / N, the light as the shading's) (default 4)",
              1, 16, &R::isophote_count, 16),
        count("topo", "number of topographic lines (heights along y, evenly across the model) (default 12)", 1, 1000,
              &R::topo_count, 100),
        real("line-width", "PX", "line width in pixels (default 2)", 0.1f, 64, &R::line_width, 0.5f, 8, false,
             "%.1f px"),
        switch_setting("fade",
                       "fade weak lines towards their threshold: suggestive contours and highlights, ridges and "
                       "valleys, apparent ridges, principal highlights (default on)",
                       &R::fade, "fade"),
        {"vectors", "LIST",
         "direction glyphs (at about one vertex per 600 pixels of the image), comma list of: normal, principal1, "
         "principal2, asymptotic, view, "
         "none (default none)",
         "a comma list of " + cli::join(render::vector_names(), ", ") + ", or none",
         word(render::parse_vectors, &R::vectors)},
        switch_setting("hidden-lines", "also draw the hidden parts of the chosen lines, dashed and light (default off)",
                       &R::hidden_lines, "hidden lines, dashed"),
        choice_setting("shading", render::shading_names(),
                       "surface shading: none (white paper), lambert, toon (three greys), hemisphere, toon-bw (two "
                       "tones), gooch (cool to warm) (default lambert)",
                       render::parse_shading, &R::shading, "shading"),
        [] {
            AppearanceSetting a{"light", "X,Y,Z",
                                "direction towards the light in camera coordinates (x right, y up, z towards the "
                                "viewer; default -0.35,0.45,1)",
                                "X,Y,Z, not all zero", [](R& s, const std::string& v) {
                                    auto d = cli::parse_vec3(v);
                                    if (!d || !(std::fabs(d->x) + std::fabs(d->y) + std::fabs(d->z) > 0)) return false;
                                    s.light_dir = *d;
                                    return true;
                                }};
            a.vec3 = &R::light_dir, a.slider_min = -1, a.slider_max = 1, a.format = "%.2f";
            return a;
        }(),
        [] {
            AppearanceSetting a{"light-frame", "camera|model",
                                "what --light is fixed to: the camera (the light moves with the view) or the model "
                                "(it turns with the model) (default camera)",
                                "camera or model", [](R& s, const std::string& v) {
                                    if (v != "camera" && v != "model") return false;
                                    s.light_on_model = v == "model";
                                    return true;
                                }};
            a.choices = {"camera", "model"};
            a.get = [](const R& s) { return std::string(s.light_on_model ? "model" : "camera"); };
            a.label = "frame";  // the light's, drawn under its direction
            return a;
        }(),
        choice_setting("colormap", render::colormap_names(), "curvature colour map (default none)",
                       render::parse_colormap, &R::colormap, "colour map"),
        switch_setting("colorbar", "draw the colour map's legend, with its values, at the right edge (default off)", &R::colorbar,
                       "colour bar", true),
        choice_setting("hatching", render::hatching_names(),
                       "principal-direction hatching: strokes along the min or max direction, or both (default none)",
                       render::parse_hatching, &R::hatching, "hatching"),
        real("hatch-spacing", "PX", "pixels between hatching strokes in the darkest tone (default 4)", 2, 100,
             &R::hatch_spacing, 2, 30, false, "%.1f px"),
        choice_setting("hatch-style", render::hatch_style_names(),
                       "how hatching is drawn: streamlines (evenly spaced, traced on the CPU, attached to the "
                       "surface; the viewer draws shader strokes while the view moves) or shader (strokes drawn "
                       "by the GPU in the surface pass, fixed to the window; raster output only) "
                       "(default streamlines)",
                       render::parse_hatch_style, &R::hatch_style, "hatch style"),
        real("min-stroke", "PX", "vector output: drop visible paths shorter than PX pixels (default 0: keep all)", 0,
             1e6f, &R::min_stroke, 0, 50, false, "%.1f px"),
        real("simplify", "PX", "vector output: simplify paths within PX pixels (Douglas-Peucker; default 0.25, 0: off)",
             0, 100, &R::simplify, 0, 2, false, "%.2f px"),
        real("taper", "PX", "vector output: stroke ends thin out over PX pixels (default 0: off)", 0, 1000, &R::taper,
             0, 50, false, "%.1f px"),
        output_switch("width-by-strength", "vector output: show fading as stroke width instead of opacity (default off)",
                      &R::width_by_strength),
        output_switch("plotter",
                      "vector output for pen plotters: one pen width, no line drawn twice, paths joined where they "
                      "meet and ordered to shorten pen travel (default off)",
                      &R::plotter, true),
        [] {
            AppearanceSetting a{"background", "COLOR", "white, transparent, black or #rrggbb (default white)",
                                "white, transparent, black or #rrggbb", word(render::parse_background, &R::background)};
            a.vec4 = &R::background, a.color = true;
            return a;
        }(),
        [] {
            AppearanceSetting a{"line-color", "COLOR", "colour of the lines: black, white or #rrggbb (default black)",
                                "black, white or #rrggbb", word(render::parse_color, &R::line_color)};
            a.vec3 = &R::line_color, a.color = true, a.label = "line colour";
            return a;
        }(),
        switch_setting("msaa", "4x multisampling of the surface (default on; unused by a white unlit surface on white, which has no edge to smooth)", &R::msaa, "4x MSAA"),
        {"line-extraction", "auto|compute|gpu|cpu",
         "where the lines are extracted: in compute shaders (GL 4.3 or later), in geometry shaders (any GL), on "
         "the CPU (fast on software GL such as llvmpipe), or auto: compute on hardware GL 4.3 or later, the CPU "
         "on software GL, else geometry shaders (default auto)",
         "auto, compute, gpu or cpu",
         [](R& s, const std::string& v) {
             if (v == "auto") s.line_extraction = render::LineExtraction::Auto;
             else if (v == "compute") s.line_extraction = render::LineExtraction::Compute;
             else if (v == "gpu") s.line_extraction = render::LineExtraction::Gpu;
             else if (v == "cpu") s.line_extraction = render::LineExtraction::Cpu;
             else return false;
             return true;
         }},
    };
    return table;
}

const std::vector<LineGroup>& line_groups() {
    static const std::vector<LineGroup> groups = {
        {"Contours",
         {{"contours", "contours", ""},
          {"silhouette", "exterior silhouette", ""},
          {"suggestive", "suggestive", "sc-threshold"},
          {"suggestive-highlights", "suggestive highlights", "sh-threshold"},
          {"dwkr", "Dw kr = threshold", "sc-threshold"},
          {"boundaries", "boundaries", ""},
          {"creases", "creases", ""}}},
        {"Ridges",
         {{"ridges", "ridges", "rv-threshold"},
          {"valleys", "valleys", "rv-threshold"},
          {"apparent-ridges", "apparent ridges", "ar-threshold"},
          {"principal-highlights", "principal highlights", "ph-threshold"}}},
        {"Curvature and levels",
         {{"parabolic", "parabolic (K = 0)", ""},
          {"mean-zero", "H = 0", ""},
          {"isophotes", "isophotes", "isophotes"},
          {"topo", "topographic", "topo"}}},
    };
    return groups;
}

const AppearanceSetting* find_appearance_setting(const std::string& name) {
    for (const auto& s : appearance_settings())
        if (s.name == name) return &s;
    return nullptr;
}

}  // namespace kappa::app
