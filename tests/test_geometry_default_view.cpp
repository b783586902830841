// The default view (geometry/view/default_view.h): angles and directions,
// and a cube seen from three-quarters, three faces at once.
#include "geometry/view/default_view.h"

#include <glm/geometric.hpp>

#include "test_shapes.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace kappa;

TEST_CASE("view_direction: azimuth around y from +z towards +x, elevation above the xz plane", "[view]") {
    auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-6f; };
    CHECK(near(view_direction({0, 0}), {0, 0, 1}));
    CHECK(near(view_direction({90, 0}), {1, 0, 0}));
    CHECK(near(view_direction({-90, 0}), {-1, 0, 0}));
    CHECK(near(view_direction({0, 90}), {0, 1, 0}));
    CHECK(glm::length(view_direction({37, 21})) == Approx(1.0f));
}

TEST_CASE("The default view of a cube is a three-quarter view that sees three faces", "[view]") {
    const Mesh cube = test::unit_cube();
    const ViewAngles a = choose_default_view(cube);
    INFO("azimuth " << a.azimuth << ", elevation " << a.elevation);
    CHECK(std::fmod(std::fabs(a.azimuth), 90.0f) != 0.0f);  // never a plain front or side view
    CHECK(a.elevation > 0);
    // Each of the three faces turned towards the eye gets a fair share of the picture.
    const glm::vec3 d = view_direction(a);
    const glm::vec3 normals[] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    float total = 0, least = 1e9f;
    int seen = 0;
    for (const glm::vec3& n : normals) {
        const float w = glm::dot(n, d);
        if (w > 0) total += w, least = std::min(least, w), ++seen;
    }
    CHECK(seen == 3);
    CHECK(least / total > 0.2f);  // the isometric view gives 1/3 each
}

TEST_CASE("The default view does not depend on the order of the faces or on a mesh without area", "[view]") {
    Mesh cube = test::unit_cube();
    const ViewAngles a = choose_default_view(cube);
    std::reverse(cube.faces.begin(), cube.faces.end());
    const ViewAngles b = choose_default_view(cube);
    CHECK(a.azimuth == b.azimuth);
    CHECK(a.elevation == b.elevation);
    Mesh flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    flat.faces = {{0, 1, 2}};
    const ViewAngles c = choose_default_view(flat);
    CHECK(c.azimuth == 30.0f);
    CHECK(c.elevation == 20.0f);
}
