// The one table of appearance settings (app/appearance_settings.h) that the
// command line, the viewer's script and the panel read: every setting the
// panel draws from words (a checkbox or a combo box) reads back what it set,
// names its default among its choices, and refuses words it does not list.
#include <catch2/catch.hpp>

#include "app/appearance_settings.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <string>

using namespace kappa;

TEST_CASE("settings drawn from words read back each word they take, and the default is one of them",
          "[render][settings]") {
    size_t with_choices = 0;
    std::set<std::string> names;
    for (const app::AppearanceSetting& a : app::appearance_settings()) {
        INFO("--" << a.name);
        CHECK(names.insert(a.name).second);  // declared once
        CHECK(!a.help.empty());
        if (a.choices.empty()) continue;
        ++with_choices;
        REQUIRE(a.get);
        const render::RenderSettings defaults;
        const std::string d = a.get(defaults);
        CHECK(std::find(a.choices.begin(), a.choices.end(), d) != a.choices.end());
        CHECK(a.help.find(d) != std::string::npos);  // the help names the default
        for (const std::string& choice : a.choices) {
            render::RenderSettings s;
            INFO("choice " << choice);
            REQUIRE(a.set(s, choice));
            CHECK(a.get(s) == choice);
        }
        render::RenderSettings s;
        CHECK(!a.set(s, "no-such-word"));
        CHECK(a.get(s) == d);
    }
    // shading, light-frame, colormap, colorbar, hatching, fade, hidden-lines, msaa
    CHECK(with_choices >= 8);
}

// The panel draws numbers, vectors and colours from the fields the table
// names: what the command line sets is what the widget shows.
TEST_CASE("settings drawn as sliders and colours edit the field their text sets", "[render][settings]") {
    size_t drawn = 0;
    for (const app::AppearanceSetting& a : app::appearance_settings()) {
        INFO("--" << a.name);
        render::RenderSettings s;
        if (a.number) {
            ++drawn;
            CHECK(a.slider_min < a.slider_max);
            REQUIRE(a.set(s, "3"));
            CHECK(s.*a.number == 3.0f);
            if (a.can_be_off) {
                REQUIRE(a.set(s, "off"));
                CHECK(s.*a.number == 0.0f);
                CHECK(render::RenderSettings{}.*a.number > 0.0f);  // what switching it on restores
            }
        } else if (a.integer) {
            ++drawn;
            REQUIRE(a.set(s, "3"));
            CHECK(s.*a.integer == 3);
        } else if (a.vec3 && a.color) {
            ++drawn;
            REQUIRE(a.set(s, "#ff8000"));
            CHECK(s.*a.vec3 == glm::vec3(1.0f, 128.0f / 255.0f, 0.0f));
            CHECK(!a.set(s, "transparent"));
        } else if (a.vec3) {
            ++drawn;
            REQUIRE(a.set(s, "0.5,-0.25,1"));
            CHECK(s.*a.vec3 == glm::vec3(0.5f, -0.25f, 1.0f));
            CHECK(!a.set(s, "0,0,0"));
        } else if (a.vec4) {
            ++drawn;
            REQUIRE(a.set(s, "transparent"));
            CHECK((s.*a.vec4).a == 0.0f);
            REQUIRE(a.set(s, "#000000"));
            CHECK(s.*a.vec4 == glm::vec4(0, 0, 0, 1));
        }
    }
    // thresholds, counts, widths, detail, light, line colour, background
    CHECK(drawn >= 14);
    const app::AppearanceSetting* detail = app::find_appearance_setting("detail");
    REQUIRE(detail);
    CHECK(detail->can_be_off);
    CHECK(app::find_appearance_setting("line-color"));
}

// Each row's text sets the RenderSettings field its name says: a row wired to
// another field (its setter and getter agreeing with each other) fails here.
TEST_CASE("every appearance setting sets the field its name says", "[render][settings]") {
    using render::RenderSettings;
    struct Expect {
        std::string value;
        std::function<bool(const RenderSettings&)> check;
    };
    const std::map<std::string, Expect> expected = {
        {"lines", {"ridges,topo", [](const RenderSettings& s) {
                       return s.lines.ridges && s.lines.topo && !s.lines.contours && !s.lines.suggestive &&
                              !s.lines.valleys && !s.lines.creases;
                   }}},
        {"detail", {"7", [](const RenderSettings& s) { return s.detail == 7.0f; }}},
        {"crease-angle", {"33", [](const RenderSettings& s) { return s.crease_angle == 33.0f; }}},
        {"sc-threshold", {"0.31", [](const RenderSettings& s) { return s.sc_threshold == 0.31f; }}},
        {"rv-threshold", {"0.32", [](const RenderSettings& s) { return s.rv_threshold == 0.32f; }}},
        {"ar-threshold", {"0.33", [](const RenderSettings& s) { return s.ar_threshold == 0.33f; }}},
        {"sh-threshold", {"0.34", [](const RenderSettings& s) { return s.sh_threshold == 0.34f; }}},
        {"ph-threshold", {"0.35", [](const RenderSettings& s) { return s.ph_threshold == 0.35f; }}},
        {"isophotes", {"7", [](const RenderSettings& s) { return s.isophote_count == 7; }}},
        {"topo", {"9", [](const RenderSettings& s) { return s.topo_count == 9; }}},
        {"line-width", {"3.5", [](const RenderSettings& s) { return s.line_width == 3.5f; }}},
        {"fade", {"off", [](const RenderSettings& s) { return !s.fade; }}},
        {"vectors", {"principal2,view", [](const RenderSettings& s) {
                         return s.vectors == (render::kGlyphPrincipal2 | render::kGlyphView);
                     }}},
        {"hidden-lines", {"on", [](const RenderSettings& s) { return s.hidden_lines; }}},
        {"shading", {"gooch", [](const RenderSettings& s) { return s.shading == render::Shading::Gooch; }}},
        {"light", {"0.5,-0.25,1", [](const RenderSettings& s) { return s.light_dir == glm::vec3(0.5f, -0.25f, 1); }}},
        {"light-frame", {"model", [](const RenderSettings& s) { return s.light_on_model; }}},
        {"colormap", {"gaussian", [](const RenderSettings& s) { return s.colormap == render::ColorMap::Gaussian; }}},
        {"colorbar", {"on", [](const RenderSettings& s) { return s.colorbar; }}},
        {"hatching", {"max", [](const RenderSettings& s) { return s.hatching == render::Hatching::Max; }}},
        {"hatch-spacing", {"6.5", [](const RenderSettings& s) { return s.hatch_spacing == 6.5f; }}},
        {"hatch-style", {"shader", [](const RenderSettings& s) { return s.hatch_style == render::HatchStyle::Shader; }}},
        {"min-stroke", {"4.5", [](const RenderSettings& s) { return s.min_stroke == 4.5f; }}},
        {"simplify", {"0.75", [](const RenderSettings& s) { return s.simplify == 0.75f; }}},
        {"taper", {"8.5", [](const RenderSettings& s) { return s.taper == 8.5f; }}},
        {"width-by-strength", {"on", [](const RenderSettings& s) { return s.width_by_strength; }}},
        {"plotter", {"on", [](const RenderSettings& s) { return s.plotter; }}},
        {"background", {"#ff8000", [](const RenderSettings& s) {
                            return s.background == glm::vec4(1, 128.0f / 255.0f, 0, 1);
                        }}},
        {"line-color", {"#0080ff", [](const RenderSettings& s) {
                            return s.line_color == glm::vec3(0, 128.0f / 255.0f, 1);
                        }}},
        {"msaa", {"off", [](const RenderSettings& s) { return !s.msaa; }}},
        {"line-extraction", {"gpu", [](const RenderSettings& s) {
                                 return s.line_extraction == render::LineExtraction::Gpu;
                             }}},
    };
    std::set<std::string> seen;
    for (const app::AppearanceSetting& a : app::appearance_settings()) {
        INFO("--" << a.name);
        const auto e = expected.find(a.name);
        CHECK(e != expected.end());  // a new setting: add its field here
        if (e == expected.end()) continue;
        seen.insert(a.name);
        const render::RenderSettings defaults;
        CHECK_FALSE(e->second.check(defaults));  // the value differs from the default
        render::RenderSettings s;
        REQUIRE(a.set(s, e->second.value));
        CHECK(e->second.check(s));
    }
    CHECK(seen.size() == expected.size());
}
