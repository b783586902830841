#include "app/viewer/ui_panel.h"

#include "app/appearance_settings.h"
#include "app/viewer/shortcuts.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace kappa::viewer {

namespace {

using render::ColorMap;

// The setting's help from the one table of settings (app/appearance_settings.h)
// as the tooltip of the widget drawn last.
void help_tooltip(const char* setting) {
    if (!ImGui::IsItemHovered()) return;
    if (const app::AppearanceSetting* a = app::find_appearance_setting(setting))
        ImGui::SetTooltip("--%s: %s", a->name.c_str(), a->help.c_str());
}

// A number, count, vector or colour of the settings table: a slider over its
// panel range (with an on/off checkbox when 0 means off), three sliders, or a
// colour picker.
void setting_slider(const app::AppearanceSetting& a, render::RenderSettings& s) {
    const ImGuiSliderFlags flags = a.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
    const std::string label = a.label.empty() ? a.name : a.label;
    if (a.number && a.can_be_off) {
        float& value = s.*a.number;
        bool on = value > 0;
        if (ImGui::Checkbox(("##" + a.name + " on").c_str(), &on)) value = on ? render::RenderSettings{}.*a.number : 0.0f;
        help_tooltip(a.name.c_str());
        ImGui::SameLine();
        if (!on) {
            ImGui::Text("%s off", label.c_str());
            help_tooltip(a.name.c_str());
            return;
        }
    }
    if (a.number)
        ImGui::SliderFloat(label.c_str(), &(s.*a.number), a.slider_min, a.slider_max, a.format, flags);
    else if (a.integer)
        ImGui::SliderInt(label.c_str(), &(s.*a.integer), int(a.slider_min), int(a.slider_max), "%d", flags);
    else if (a.vec3 && a.color)
        ImGui::ColorEdit3(label.c_str(), &(s.*a.vec3).x, ImGuiColorEditFlags_NoInputs);
    else if (a.vec3)
        ImGui::SliderFloat3(label.c_str(), &(s.*a.vec3).x, a.slider_min, a.slider_max, a.format);
    else if (a.vec4)
        ImGui::ColorEdit4(label.c_str(), &(s.*a.vec4).x, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_AlphaPreview);
    help_tooltip(a.name.c_str());
}

void setting_slider(const char* name, render::RenderSettings& s) {
    if (const app::AppearanceSetting* a = app::find_appearance_setting(name)) setting_slider(*a, s);
}

// A setting of a few words from the table: a checkbox when they are off and
// on, else a combo box; labelled as the table says, with its key if it has one.
void setting_widget(const char* name, render::RenderSettings& s) {
    const app::AppearanceSetting* a = app::find_appearance_setting(name);
    if (!a || a->choices.empty() || !a->get) return;
    std::string label = a->label.empty() ? a->name : a->label;
    if (const Shortcut* key = find_setting_shortcut(a->name)) label += std::string(" (") + key->name + ")";
    const std::string current = a->get(s);
    if (a->choices == std::vector<std::string>{"off", "on"}) {
        bool on = current == "on";
        if (ImGui::Checkbox(label.c_str(), &on)) a->set(s, on ? "on" : "off");
    } else if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
        for (const std::string& choice : a->choices)
            if (ImGui::Selectable(choice.c_str(), choice == current)) a->set(s, choice);
        ImGui::EndCombo();
    }
    help_tooltip(name);
}

// The line kinds of one of app::line_groups(): a checkbox each (with its
// key), then the sliders of the thresholds that the kinds that are on use.
void line_group(const app::LineGroup& group, render::RenderSettings& s) {
    ImGui::TextDisabled("%s", group.title.c_str());
    std::vector<std::string> sliders;
    for (const app::LineToggle& t : group.lines) {
        const render::LineKind* kind = render::find_line_kind(t.kind);
        if (!kind) continue;
        std::string label = t.label;
        if (const Shortcut* key = find_line_shortcut(t.kind)) label += std::string(" (") + key->name + ")";
        ImGui::Checkbox(label.c_str(), &(s.lines.*(kind->flag)));
        help_tooltip(t.setting.empty() ? "lines" : t.setting.c_str());
        if (s.lines.*(kind->flag) && !t.setting.empty() &&
            std::find(sliders.begin(), sliders.end(), t.setting) == sliders.end())
            sliders.push_back(t.setting);
    }
    for (const std::string& name : sliders) setting_slider(name.c_str(), s);
}

void lines_section(render::RenderSettings& s) {
    if (!ImGui::CollapsingHeader("Lines", ImGuiTreeNodeFlags_DefaultOpen)) return;
    for (const app::LineGroup& g : app::line_groups()) line_group(g, s);
    ImGui::Separator();
    setting_widget("hidden-lines", s);
    ImGui::SameLine();
    setting_widget("fade", s);
    // Direction glyphs: one checkbox a direction, as --vectors names them.
    const std::vector<std::string>& glyphs = render::vector_names();
    ImGui::TextUnformatted("vectors");
    for (int i = 0; i < int(glyphs.size()); ++i) {
        if (i != 2) ImGui::SameLine();  // two rows: the panel is narrow
        bool on = (s.vectors >> i) & 1;
        if (ImGui::Checkbox(glyphs[size_t(i)].c_str(), &on)) s.vectors = on ? s.vectors | (1 << i) : s.vectors & ~(1 << i);
        help_tooltip("vectors");
    }
    setting_slider("detail", s);
    setting_slider("line-width", s);
    setting_slider("line-color", s);
}

void surface_section(render::RenderSettings& s, float map_range) {
    if (!ImGui::CollapsingHeader("Surface", ImGuiTreeNodeFlags_DefaultOpen)) return;
    setting_widget("shading", s);
    setting_slider("light", s);
    setting_widget("light-frame", s);
    if (glm::length(s.light_dir) < 1e-3f) s.light_dir = {0, 0, 1};
    setting_widget("colormap", s);
    if (s.colormap != ColorMap::None) {
        setting_widget("colorbar", s);
        if (s.colormap == ColorMap::DCurv)
            ImGui::Text("range [0, %.4g]", map_range);
        else
            ImGui::Text("range [-%.4g, %.4g]", map_range, map_range);
    }
    setting_widget("hatching", s);
    if (s.hatching != render::Hatching::None) {
        setting_slider("hatch-spacing", s);
        setting_widget("hatch-style", s);
    }
    setting_slider("background", s);
    setting_widget("msaa", s);
}

// Widths as multiples of the feature size are easier to choose than model units.
bool smoothing_section(SmoothingOptions& sm, const Model* model, bool computing, float progress,
                       const std::string& stage) {
    if (!ImGui::CollapsingHeader("Curvature smoothing", ImGuiTreeNodeFlags_DefaultOpen)) return false;
    const float fs = model ? model->feature_size : 1.0f;
    bool recompute = false;
    auto width = [&](const char* label, float& sigma) {
        float in_fs = sigma / fs;
        if (ImGui::SliderFloat(label, &in_fs, 0.0f, 2.0f, in_fs > 0 ? "%.3f fs" : "off")) sigma = in_fs * fs;
        recompute |= ImGui::IsItemDeactivatedAfterEdit();
    };
    if (ImGui::BeginCombo("estimator", estimator_name(sm.estimator).c_str())) {
        for (size_t i = 0; i < estimator_names().size(); ++i)
            if (ImGui::Selectable(estimator_names()[i].c_str(), size_t(sm.estimator) == i)) {
                recompute |= sm.estimator != Estimator(i);
                sm.estimator = Estimator(i);
            }
        ImGui::EndCombo();
    }
    // auto: widths left at 0 are chosen from the mesh's noise level (docs/detail-and-noise.md).
    if (ImGui::Checkbox("auto (from the noise level)", &sm.automatic)) recompute = true;
    width("normals", sm.normals);
    width("curvature", sm.curvature);
    width("derivative C", sm.dcurv);
    ImGui::TextDisabled("Gaussian sigma, fs = %.4g model units", fs);
    if (model && model->fields->smoothing.automatic) {
        const SmoothingOptions& used = model->fields->smoothing;
        ImGui::TextDisabled("noise %.3g edges; used %.3f, %.3f, %.3f fs", model->fields->noise.relative,
                            used.normals / fs, used.curvature / fs, used.dcurv / fs);
    }
    if (computing) {
        char overlay[64];
        std::snprintf(overlay, sizeof overlay, "%s %d%%", stage.c_str(), int(progress * 100));
        ImGui::ProgressBar(progress, ImVec2(-1, 0), overlay);
    }
    return recompute;
}

void mesh_section(const PanelInfo& info) {
    if (!ImGui::CollapsingHeader("Mesh", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const Model* m = info.model;
    if (!m) {
        ImGui::TextUnformatted("loading...");
        return;
    }
    ImGui::TextWrapped("%s", m->path.empty() ? "built-in model" : m->path.c_str());
    ImGui::Text("%zu vertices, %zu faces", m->mesh->vertex_count(), m->mesh->face_count());
    ImGui::Text("%zu boundary, %zu flagged vertices", m->summary.boundary_vertices, m->summary.flagged_vertices);
    ImGui::Text("feature size %.4g", m->feature_size);
    ImGui::Text("k1 in [%.4g, %.4g]", m->summary.k1_min, m->summary.k1_max);
    ImGui::Text("k2 in [%.4g, %.4g]", m->summary.k2_min, m->summary.k2_max);
    ImGui::Text("load %.3f s, curvature %.3f s", m->load_s, m->fields_s);
    ImGui::Text("upload %.3f s, first frame at %.3f s", info.upload_s, info.first_frame_s);
}

void file_section(PanelState& panel, PanelRequests& r) {
    if (!ImGui::CollapsingHeader("Files")) return;
    ImGui::InputText("##open", &panel.open_path);
    ImGui::SameLine();
    r.open = ImGui::Button("Open mesh");
    ImGui::InputText("##png", &panel.screenshot_path);
    ImGui::SameLine();
    r.screenshot = ImGui::Button("Screenshot");
    ImGui::Checkbox("with the panel", &panel.screenshot_with_panel);
    ImGui::TextDisabled(".png/.jpg: pixels; .svg/.pdf: the drawing as vector strokes");
    ImGui::InputText("##xf", &panel.view_path);
    ImGui::SameLine();
    r.save_view = ImGui::Button("Save");
    ImGui::SameLine();
    r.load_view = ImGui::Button("Load");
    ImGui::TextDisabled("views are trimesh2/rtsc .xf files: kappa render --xf");
}

}  // namespace

float panel_width(float ui_scale) { return 330.0f * ui_scale; }

PanelRequests draw_panel(ViewState& state, PanelState& panel, const PanelInfo& info, float ui_scale) {
    PanelRequests r;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(panel_width(ui_scale), display.y), ImGuiCond_Always);
    ImGui::Begin("kappa", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(-115 * ui_scale);  // room for the labels
    ImGui::Text("%.1f ms/frame (%.0f fps)", info.frame_ms, info.frame_ms > 0 ? 1000.0f / info.frame_ms : 0.0f);
    r.fit = ImGui::Button("Fit (F)");
    ImGui::SameLine();
    r.reset = ImGui::Button("Reset (R)");
    ImGui::SameLine();
    if (ImGui::Button("Help (F1)")) panel.help = !panel.help;
    ImGui::Checkbox("fast while moving", &panel.fast_while_moving);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("no multisampling while dragging when frames take over 33 ms");
    lines_section(state.settings);
    surface_section(state.settings, info.map_range);
    r.recompute = smoothing_section(state.smoothing, info.model, info.computing && info.progress >= 0, info.progress,
                                    info.stage);
    mesh_section(info);
    file_section(panel, r);
    if (!panel.message.empty()) ImGui::TextWrapped("%s", panel.message.c_str());
    ImGui::TextWrapped("%s", info.gl.c_str());
    ImGui::PopItemWidth();
    ImGui::End();
    return r;
}

void draw_help_window(bool* open, float ui_scale) {
    if (!*open) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(440 * ui_scale, 0), ImGuiCond_Appearing);
    if (ImGui::Begin("Help", open, ImGuiWindowFlags_NoCollapse)) {
        ImGui::TextUnformatted("Mouse");
        ImGui::BulletText("left drag: orbit (trackball)");
        ImGui::BulletText("right or middle drag: pan");
        ImGui::BulletText("wheel: zoom toward the cursor");
        ImGui::BulletText("drop a mesh file on the window to open it");
        ImGui::Separator();
        ImGui::TextUnformatted("Keys");
        if (ImGui::BeginTable("keys", 2)) {
            ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed, 60 * ui_scale);
            ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
            for (const auto& s : shortcuts()) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(s.name);
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(s.description);
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
}

void draw_progress_overlay(const PanelInfo& info, float ui_scale) {
    if (!info.computing) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y - 20 * ui_scale), ImGuiCond_Always, ImVec2(0.5f, 1));
    ImGui::SetNextWindowSize(ImVec2(300 * ui_scale, 0), ImGuiCond_Always);
    ImGui::Begin("##progress", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings);
    char overlay[64];
    if (info.progress >= 0) {
        std::snprintf(overlay, sizeof overlay, "%s %d%%", info.stage.c_str(), int(info.progress * 100));
        ImGui::ProgressBar(info.progress, ImVec2(-1, 0), overlay);
    } else {  // no fraction known: a bar that keeps moving
        std::snprintf(overlay, sizeof overlay, "%s", info.stage.c_str());
        ImGui::ProgressBar(float(std::fmod(ImGui::GetTime() * 0.5, 1.0)), ImVec2(-1, 0), overlay);
    }
    ImGui::End();
}

}  // namespace kappa::viewer
