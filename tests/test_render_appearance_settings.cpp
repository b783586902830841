// The one table of appearance settings (app/appearance_settings.h) that the
// command line, the viewer's script and the panel read: every setting the
// panel draws from words (a checkbox or a combo box) reads back what it set,
// names its default among its choices, and refuses words it does not list.
#include <catch2/catch.hpp>

#include "app/appearance_settings.h"

#include <algorithm>
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
