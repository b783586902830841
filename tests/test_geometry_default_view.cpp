// The default view (geometry/view/default_view.h): angles and directions,
// and a cube seen from three-quarters, three faces at once.
#include "geometry/view/default_view.h"
#include "geometry/io/mesh_io.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include "test_shapes.h"
#include "test_support.h"

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

namespace {

// A toy animal: a long body along z (legs below it) with a tall head at the
// front end, at z = front_z.
Mesh toy_animal(float front_z) {
    const float s = front_z > 0 ? 1.0f : -1.0f;
    Mesh m = test::box({-0.5f, 0.0f, -1.5f}, {0.5f, 1.0f, 1.5f});
    for (float x : {-0.4f, 0.2f})
        for (float z : {-1.3f, 1.1f}) test::append(m, test::box({x, -1.0f, z}, {x + 0.2f, 0.0f, z + 0.2f}));
    test::append(m, test::box({-0.4f, 0.5f, std::min(s * 1.2f, s * 2.2f)}, {0.4f, 1.8f, std::max(s * 1.2f, s * 2.2f)}));
    return m;
}

float towards(ViewAngles a, glm::vec2 front) {
    const glm::vec3 d = view_direction(a);
    return glm::dot(glm::normalize(glm::vec2(d.x, d.z)), front);
}

}  // namespace

TEST_CASE("The default view never shows a model with a front from behind", "[view]") {
    // The head (the tallest part) at -z, then at +z: the view comes from
    // within 50 degrees of that end, whichever it is.
    for (float front_z : {-1.0f, 1.0f}) {
        const ViewAngles a = choose_default_view(toy_animal(front_z));
        INFO("head towards z " << front_z << ": azimuth " << a.azimuth);
        CHECK(towards(a, {0, front_z}) >= std::cos(glm::radians(50.0f)) - 1e-5f);
    }
    // Spot the cow faces -z; shape alone prefers its rump (see default_view.h).
    const ViewAngles spot = choose_default_view(load_mesh(test::shared_mesh("spot.obj")));
    INFO("spot: azimuth " << spot.azimuth);
    CHECK(towards(spot, {0, -1}) >= std::cos(glm::radians(50.0f)) - 1e-5f);
    CHECK(std::fmod(std::fabs(spot.azimuth), 90.0f) != 0.0f);  // still three-quarter
}

TEST_CASE("The front rule leaves models without a front alone", "[view]") {
    // A long box with a level top has no front: its view is the same as the
    // same box turned by 180 degrees, mirrored.
    const Mesh bar = test::box({-0.5f, 0.0f, -1.5f}, {0.5f, 1.0f, 1.5f});
    Mesh turned = bar;
    for (glm::vec3& p : turned.positions) p = {-p.x, p.y, -p.z};
    const ViewAngles a = choose_default_view(bar), b = choose_default_view(turned);
    const glm::vec3 da = view_direction(a), db = view_direction(b);
    INFO("azimuths " << a.azimuth << ", " << b.azimuth);
    // Both are among the equally good symmetric views: same elevation, and
    // the same angle to the long axis.
    CHECK(a.elevation == b.elevation);
    CHECK(std::fabs(std::fabs(da.z) - std::fabs(db.z)) < 1e-5f);
}

TEST_CASE("The default view with the vertex-face rows given is the same, to the last bit", "[view]") {
    Mesh zup = load_mesh(test::shared_mesh("spot.obj"));
    for (glm::vec3& p : zup.positions) p = {p.x, -p.z, p.y};  // stood on +z
    std::vector<std::pair<const char*, Mesh>> meshes;
    for (const char* name : {"bunny.ply", "fandisk.obj", "spot.obj", "dragon-50k.ply"})
        meshes.push_back({name, load_mesh(test::shared_mesh(name))});
    meshes.push_back({"spot, z up", zup});
    // Big enough (4.8M faces or more) for the sampled vertices' normals to be summed from the rows.
    Mesh hills;
    const int n = 1560;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = float(i) / float(n), y = float(j) / float(n);
            const float height = 0.1f * std::sin(17.0f * x) * std::cos(11.0f * y) + 0.002f * std::sin(float(i * j));
            hills.positions.push_back({x, height, y});
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const uint32_t a = uint32_t(j * n + i), b = a + 1, c = a + uint32_t(n), d = c + 1;
            hills.faces.push_back({a, d, b});
            hills.faces.push_back({a, c, d});
        }
    REQUIRE(hills.face_count() >= 24 * 200000);
    meshes.push_back({"hills", std::move(hills)});
    for (const auto& [name, mesh] : meshes) {
        INFO(name);
        const VertexFaces vf = build_vertex_faces(mesh);
        for (const std::optional<glm::vec3> up : {std::optional<glm::vec3>(), std::optional<glm::vec3>({0, 0, 1})}) {
            const DefaultView without = default_view_as_read(mesh, up);
            const DefaultView with = default_view_as_read(mesh, up, false, &vf);
            CHECK(with.eye == without.eye);
            CHECK(with.up == without.up);
            CHECK(with.angles.azimuth == without.angles.azimuth);
            CHECK(with.angles.elevation == without.angles.elevation);
        }
    }
}
