// The default view's up axis and its view about it
// (geometry/view/default_view.h: choose_up, view_frame, default_view), on
// procedural shapes in several orientations, the shared meshes and
// degenerate input.
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/primitives.h"
#include "geometry/scale/denoise.h"
#include "geometry/view/default_view.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "test_shapes.h"
#include "test_upright_shapes.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>

using namespace kappa;
using namespace kappa::test;

namespace {

float degrees_between(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

// Cosine between the eye's direction across the up axis and `front`.
float towards(const DefaultView& v, glm::vec3 front) {
    const glm::vec3 across = v.eye - glm::dot(v.eye, v.up) * v.up;
    return glm::dot(glm::normalize(across), glm::normalize(front));
}

// The mean length of the mesh's face edges.
float mean_edge(const Mesh& m) {
    double sum = 0;
    for (const Face& f : m.faces)
        for (int k = 0; k < 3; ++k) sum += glm::length(m.positions[f[(k + 1) % 3]] - m.positions[f[k]]);
    return float(sum / (3.0 * double(m.face_count())));
}

bool finite_unit(glm::vec3 v) { return std::isfinite(v.x + v.y + v.z) && std::fabs(glm::length(v) - 1) < 1e-4f; }

}  // namespace

TEST_CASE("view_frame turns +y onto up by the smallest rotation, right-handed", "[view]") {
    auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-5f; };
    const ViewFrame y = view_frame({0, 2, 0});
    CHECK(y.right == glm::vec3(1, 0, 0));
    CHECK(y.front == glm::vec3(0, 0, 1));
    const ViewFrame z = view_frame({0, 0, 1});
    CHECK(near(z.right, {1, 0, 0}));
    CHECK(near(z.front, {0, -1, 0}));  // the front view of z-up tools looks from -y
    const ViewFrame down = view_frame({0, -1, 0});
    CHECK(near(down.front, {0, 0, -1}));
    for (glm::vec3 u : {glm::vec3(1, 0, 0), glm::vec3(0.3f, -0.2f, 0.9f), glm::vec3(0, -1, 1e-6f)}) {
        const ViewFrame f = view_frame(u);
        INFO("up " << u.x << "," << u.y << "," << u.z);
        CHECK(near(f.up, glm::normalize(u)));
        CHECK(near(glm::cross(f.right, f.up), f.front));
        CHECK(std::fabs(glm::dot(f.right, f.up)) < 1e-5f);
        CHECK(finite_unit(f.right));
    }
    // Zero and non-finite ups fall back to y up.
    CHECK(view_frame(glm::vec3(0)).up == glm::vec3(0, 1, 0));
    CHECK(view_frame(glm::vec3(NAN, 0, 1)).up == glm::vec3(0, 1, 0));
    // Angles about an up: azimuth 0 from front, 90 from right, elevation towards up.
    CHECK(near(view_direction({0, 0}, {0, 0, 1}), {0, -1, 0}));
    CHECK(near(view_direction({90, 0}, {0, 0, 1}), {1, 0, 0}));
    CHECK(near(view_direction({0, 90}, {0, 0, 1}), {0, 0, 1}));
    CHECK(view_direction({37, 21}, {0, 1, 0}) == view_direction({37, 21}));
}

TEST_CASE("A bust scanned z up, on a flat base, is seen upright whichever axis its file calls up", "[view]") {
    const Mesh bust = bust_z_up();
    const DefaultView v = default_view(bust);
    INFO("up " << v.up.x << "," << v.up.y << "," << v.up.z);
    CHECK(degrees_between(v.up, {0, 0, 1}) < 3);
    CHECK(finite_unit(v.eye));
    // Seen from above its base, at the default elevations (20 or 35 degrees).
    const float elevation = 90 - degrees_between(v.eye, v.up);
    CHECK(elevation > 15);
    CHECK(elevation < 40);
    CHECK(towards(v, {0, -1, 0}) > 0.5f);  // from the face's side (the face looks towards -y)
    // Only z takes y's place, base down: the same bust with its base at the
    // low end of x, or at the high end of z (upside down, or a panel's flat
    // back), keeps +y.
    CHECK(choose_up(mapped(bust, [](glm::vec3 p) { return glm::vec3(p.z, p.y, p.x); })) == glm::vec3(0, 1, 0));
    CHECK(choose_up(mapped(bust, [](glm::vec3 p) { return glm::vec3(p.x, -p.y, -p.z); })) == glm::vec3(0, 1, 0));
    // Scanned y up (base at -y), it stays y up.
    CHECK(choose_up(mapped(bust, [](glm::vec3 p) { return glm::vec3(p.x, p.z, -p.y); })) == glm::vec3(0, 1, 0));
}

TEST_CASE("A head scanned y up stays y up and is seen from its face side, with or without hair", "[view]") {
    const Mesh head = head_y_up();
    const DefaultView v = default_view(head);
    CHECK(v.up == glm::vec3(0, 1, 0));
    CHECK(v.eye.y > 0);  // from above
    // The face looks towards +z; turned about y, it still gets the view:
    // within 50 degrees of the face (the never-from-behind rule's band).
    for (const Mesh& m : {head, head_with_hair_y_up()})
        for (float deg : {0.0f, 30.0f, 100.0f, 180.0f, 250.0f}) {
            const float a = glm::radians(deg), c = std::cos(a), s = std::sin(a);
            const Mesh turned = mapped(m, [&](glm::vec3 p) { return glm::vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z); });
            const DefaultView t = default_view(turned);
            INFO("turned by " << deg << " degrees, " << m.face_count() << " faces: eye " << t.eye.x << "," << t.eye.y
                              << "," << t.eye.z);
            CHECK(t.up == glm::vec3(0, 1, 0));
            CHECK(towards(t, {s, 0, c}) >= std::cos(glm::radians(50.0f)) - 1e-4f);
        }
    // The same head z up (neck at -z): upright.
    const Mesh z_up = mapped(head, [](glm::vec3 p) { return glm::vec3(p.x, -p.z, p.y); });
    CHECK(degrees_between(choose_up(z_up), {0, 0, 1}) < 3);
}

// Scan noise of 0.1, 0.33 and 0.5 mean edges along the normals: the noisy
// shape is read at its noise floor (default_view.h) and gets the clean
// shape's up and about its view. The shapes are mirror-symmetric about
// x = 0, so their three-quarter views from the left and from the right are
// equally good (the clean scores differ by tessellation alone) and the eye
// is compared with the clean one's or its mirror image. Measured (seeds 1-3):
// up unchanged; the eye within 24.5 degrees of the clean one's or its mirror
// (azimuth two 15-degree steps off at elevation 35); without the denoising
// the bust fell onto its side (y up) from 0.33 edges and the head was seen
// from +-75 to 105 degrees off its face. Bound 30 degrees.
TEST_CASE("A noisy scan of a bust or a head is seen as its clean shape is", "[view]") {
    std::vector<std::pair<std::string, Mesh>> shapes;
    shapes.push_back({"bust z up", bust_z_up()});
    shapes.push_back({"head y up", head_y_up()});
    shapes.push_back({"head with hair", head_with_hair_y_up()});
    for (const auto& [name, clean] : shapes) {
        const DefaultView c = default_view(clean);
        const glm::vec3 mirrored_eye(-c.eye.x, c.eye.y, c.eye.z);
        for (float eta : {0.1f, 0.33f, 0.5f}) {
            Mesh noisy = clean;
            add_normal_noise(noisy, eta * mean_edge(clean), 1);
            const DefaultView v = default_view(noisy);
            INFO(name << ", noise " << eta << " edges: eye " << v.eye.x << "," << v.eye.y << "," << v.eye.z << " up "
                      << v.up.x << "," << v.up.y << "," << v.up.z << "; clean eye " << c.eye.x << "," << c.eye.y
                      << "," << c.eye.z);
            CHECK(degrees_between(v.up, c.up) < 3);
            CHECK(std::min(degrees_between(v.eye, c.eye), degrees_between(v.eye, mirrored_eye)) < 30);
        }
    }
}

TEST_CASE("A standing figure is seen upright along its long axis", "[view]") {
    const Mesh figure = figure_z_up();
    const DefaultView v = default_view(figure);
    INFO("up " << v.up.x << "," << v.up.y << "," << v.up.z);
    CHECK(degrees_between(v.up, {0, 0, 1}) < 3);
    CHECK(glm::dot(v.eye, v.up) > 0);
    // y up in its file: left so. Standing on its head: left as it is.
    CHECK(choose_up(mapped(figure, [](glm::vec3 p) { return glm::vec3(p.x, p.z, -p.y); })) == glm::vec3(0, 1, 0));
    CHECK(choose_up(mapped(figure, [](glm::vec3 p) { return glm::vec3(p.x, -p.y, -p.z); })) == glm::vec3(0, 1, 0));
}

// Under scan noise the figure's soles (about 3 by 4 edges) are no longer
// flat, raw or denoised (0.01-0.03% of the surface within 5 degrees of
// level against 0.9% clean): the long axis and the blunter low end say
// z up instead. Measured (default_view.h): the low end's slab holds 1.23 to
// 1.63 times the high end's surface at 0.1 to 0.5 edges of noise, seeds 1-4;
// standing on its head it is the other way round, and +y is kept. A clean
// figure without a flat base is not read so: that rule is for denoised
// scans only, as lying objects with one blunt end keep their file's +y.
TEST_CASE("A noisy scan of a standing figure stands upright, and on its head keeps +y", "[view]") {
    const Mesh figure = figure_z_up();
    const Mesh on_its_head = mapped(figure, [](glm::vec3 p) { return glm::vec3(p.x, -p.y, -p.z); });
    for (float eta : {0.1f, 0.33f, 0.5f})
        for (uint32_t seed : {1u, 2u}) {
            Mesh noisy = figure, noisy_head = on_its_head;
            add_normal_noise(noisy, eta * mean_edge(figure), seed);
            add_normal_noise(noisy_head, eta * mean_edge(figure), seed);
            const DefaultView v = default_view(noisy);
            INFO("noise " << eta << " edges, seed " << seed << ": up " << v.up.x << "," << v.up.y << "," << v.up.z);
            CHECK(degrees_between(v.up, {0, 0, 1}) < 3);
            CHECK(glm::dot(v.eye, v.up) > 0);
            CHECK(default_view(noisy_head).up == glm::vec3(0, 1, 0));
        }
    // The figure's soles smoothed away, read as given (not denoised): +y.
    Mesh noisy = figure;
    add_normal_noise(noisy, 0.33f * mean_edge(figure), 1);
    const std::optional<Mesh> denoised = denoised_if_noisy(noisy);
    REQUIRE(denoised);
    CHECK(choose_up(*denoised) == glm::vec3(0, 1, 0));
    CHECK(choose_up(*denoised, true) == glm::vec3(0, 0, 1));
}

TEST_CASE("Shapes without a clear base keep +y: a cube, a sphere, a long bar lying down, a plate", "[view]") {
    CHECK(choose_up(test::unit_cube()) == glm::vec3(0, 1, 0));
    CHECK(choose_up(make_icosphere(1, 3)) == glm::vec3(0, 1, 0));
    CHECK(choose_up(make_torus(1, 0.3f, 48, 16)) == glm::vec3(0, 1, 0));  // lying in xy: no flat end
    // A box lying along z (flat bottom at -y and flat ends): y has as much flat end.
    CHECK(choose_up(test::box({-0.5f, 0, -3}, {0.5f, 1, 3})) == glm::vec3(0, 1, 0));
    // A thin plate in xy (flat along z, but thin: seen as it stands).
    CHECK(choose_up(test::box({-1, -1, 0}, {1, 1, 0.1f})) == glm::vec3(0, 1, 0));
}

TEST_CASE("The shared meshes keep +y up and today's view", "[view]") {
    for (const char* name : {"bunny.ply", "dragon-50k.ply", "fandisk.obj", "spot.obj", "bunny-1M.ply"}) {
        const Mesh mesh = load_mesh(test::shared_mesh(name));
        const DefaultView v = default_view(mesh);
        const ViewAngles today = choose_default_view(mesh);  // the y-up rules, as before up detection
        INFO(name << ": up " << v.up.x << "," << v.up.y << "," << v.up.z);
        CHECK(v.up == glm::vec3(0, 1, 0));
        CHECK(v.angles.azimuth == today.azimuth);
        CHECK(v.angles.elevation == today.elevation);
        CHECK(v.eye == view_direction(today));
    }
}

TEST_CASE("Flat and degenerate meshes get a finite default view", "[view]") {
    std::vector<std::pair<std::string, Mesh>> meshes;
    meshes.push_back({"grid in xy", make_grid(2, 8)});
    meshes.push_back({"grid in xz", mapped(make_grid(2, 8), [](glm::vec3 p) { return glm::vec3(p.x, p.z, p.y); })});
    meshes.push_back({"grid in yz", mapped(make_grid(2, 8), [](glm::vec3 p) { return glm::vec3(p.z, p.x, p.y); })});
    meshes.push_back({"tilted grid", mapped(make_grid(2, 8), [](glm::vec3 p) {
                          return glm::vec3(p.x + p.y, p.x - p.y, 0.5f * p.y);
                      })});
    Mesh strip;
    for (int i = 0; i < 10; ++i) strip.positions.push_back({float(i / 2), float(i % 2) * 0.1f, 0});
    for (uint32_t i = 0; i + 2 < 10; ++i) strip.faces.push_back({i, i + 1, i + 2});
    meshes.push_back({"strip", strip});
    Mesh triangle;
    triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    triangle.faces = {{0, 1, 2}};
    meshes.push_back({"triangle", triangle});
    Mesh line;
    line.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    line.faces = {{0, 1, 2}};
    meshes.push_back({"collinear triangle", line});
    Mesh point;
    point.positions = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
    point.faces = {{0, 1, 2}};
    meshes.push_back({"point", point});
    meshes.push_back({"empty", Mesh{}});
    Mesh nan = triangle;
    nan.positions.push_back({NAN, 0, INFINITY});
    nan.faces.push_back({0, 1, 3});
    meshes.push_back({"non-finite vertex", nan});
    for (const auto& [name, mesh] : meshes) {
        INFO(name);
        const DefaultView v = default_view(mesh);
        CHECK(finite_unit(v.up));
        CHECK(finite_unit(v.eye));
        CHECK(degrees_between(v.eye, v.up) > 45);  // a three-quarter view, not along up
        for (glm::vec3 up : {glm::vec3(0, 0, 1), glm::vec3(1, 1, 0), glm::vec3(0, 0, 0)}) {
            const DefaultView given = default_view(mesh, up);
            CHECK(finite_unit(given.eye));
            CHECK(finite_unit(given.up));
        }
    }
}

TEST_CASE("An up given (--up, a glTF file) replaces the shape's, and glTF files are y up", "[view]") {
    const Mesh bust = bust_z_up();
    const DefaultView v = default_view(bust, glm::vec3(0, 1, 0));
    CHECK(v.up == glm::vec3(0, 1, 0));
    CHECK(v.eye == view_direction(choose_default_view(bust)));
    const DefaultView w = default_view(bust, glm::vec3(0, 0, 5));
    CHECK(degrees_between(w.up, {0, 0, 1}) < 1e-3f);
    CHECK(file_up_axis("a/b/model.GLB") == glm::vec3(0, 1, 0));
    CHECK(file_up_axis("model.gltf") == glm::vec3(0, 1, 0));
    CHECK_FALSE(file_up_axis("model.stl"));
    CHECK_FALSE(file_up_axis("dir.gltf/model"));
    CHECK_FALSE(file_up_axis(""));
}
