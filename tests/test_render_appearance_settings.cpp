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
