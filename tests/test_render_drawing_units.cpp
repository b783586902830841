// Meshes far from unit size (geometry/mesh/drawing_units.h) are drawn from a copy
// of unit size: the same picture as the mesh at its own size, with cameras
// given in model units converted; and the conversion of a view matrix keeps
// every point where it was on screen. Meshes whose faces point inwards
// (geometry/mesh/orientation.h) draw as the same mesh the right way round.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"
#include "test_support.h"

#include "app/mesh_source.h"
#include "geometry/mesh/drawing_units.h"
#include "geometry/io/mesh_io.h"
#include "render/camera/camera.h"
#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <string>

using namespace kappa;
using test::kappa_render;


TEST_CASE("kappa render draws a mesh scaled by 1e20 or 1e-20 as it draws the mesh itself", "[render][cli]") {
    // geometry/mesh/drawing_units.h: such meshes are drawn from a copy of unit size,
    // and cameras given in model units (--eye) are converted.
    const std::string dir = test::temp_dir();
    const Mesh mesh = load_mesh(test::shared_mesh("fandisk.obj"));
    const auto draw = [&](float scale, const std::string& name) {
        auto number = [](double x) {
            char text[32];
            std::snprintf(text, sizeof text, "%.9g", x);
            return std::string(text);
        };
        std::string obj;
        for (const glm::vec3& p : mesh.positions)
            obj += "v " + number(double(p.x) * scale) + " " + number(double(p.y) * scale) + " " +
                   number(double(p.z) * scale) + "\n";
        for (const Face& f : mesh.faces)
            obj += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1) + "\n";
        test::write_file(dir + "/" + name + ".obj", obj);
        // --eye without --target: only its direction counts, in model units like the mesh.
        const std::string eye = " --eye " + number(3.0 * scale) + "," + number(2.0 * scale) + "," + number(4.0 * scale);
        const auto r = test::run_command(kappa_render(dir + "/" + name + ".obj -o " + dir + "/" + name + ".png -q " +
                                                      "--size 240x180 --lines contours,suggestive,creases,ridges" + eye));
        REQUIRE(r.exit_code == 0);
        return render::read_png(dir + "/" + name + ".png");
    };
    const render::Image plain = draw(1.0f, "plain"), huge = draw(1e20f, "huge"), tiny = draw(1e-20f, "tiny");
    CHECK(test::count_ink(plain) > 500);
    // Only the last bits of the scaled coordinates (printed with 9 digits) differ.
    CHECK(render::ink_within(plain, huge, 1.0f) > 0.99);
    CHECK(render::ink_within(huge, plain, 1.0f) > 0.99);
    CHECK(render::ink_within(plain, tiny, 1.0f) > 0.99);
    CHECK(render::ink_within(tiny, plain, 1.0f) > 0.99);
}

TEST_CASE("a view matrix converted to drawing units puts every point where it was, scaled", "[render][units]") {
    Mesh mesh;
    mesh.positions = {{3e20f, 1e20f, -2e20f}, {5e20f, 2e20f, -1e20f}, {4e20f, 3e20f, 0.0f}};
    mesh.faces = {{0, 1, 2}};
    const DrawingUnits units = drawing_units(mesh);
    REQUIRE(!units.identity());
    // Built in double: in float the lengths of such vectors overflow (what drawing units avoid).
    const glm::mat4 view = glm::mat4(glm::lookAt(glm::dvec3(1e21, 2e20, 5e20), glm::dvec3(4e20, 2e20, -1e20),
                                                 glm::dvec3(0, 1, 0)));
    const glm::mat4 drawing_view = units.view_to_drawing(view);
    for (const glm::vec3& p : mesh.positions) {
        const glm::dvec4 camera = glm::dmat4(view) * glm::dvec4(glm::dvec3(p), 1.0);
        const glm::vec4 drawn = drawing_view * glm::vec4(units.to_drawing(p), 1.0f);
        for (int k = 0; k < 3; ++k) CHECK(double(drawn[k]) == Approx(camera[k] / units.scale).margin(1e-5));
    }
    // Ordinary sizes are left alone.
    Mesh unit = mesh;
    for (glm::vec3& p : unit.positions) p *= 1e-20f;
    CHECK(drawing_units(unit).identity());
}

TEST_CASE("the preparation's box is the prepared mesh's, at any size, and gives its bounding sphere",
          "[render][units]") {
    // app/mesh_source.h: the box of the drawing copy serves the units, the split mesh's bounding sphere and
    // the buffers' (MeshFacts), instead of a pass over the positions each.
    for (const float scale : {1.0f, 1e20f, 1e-20f}) {
        INFO("scale " << scale);
        Mesh mesh = load_mesh(test::shared_mesh("fandisk.obj"));
        for (glm::vec3& p : mesh.positions) p = p * scale + glm::vec3(3.0f * scale, 0, 0);
        VertexFaces rows = build_vertex_faces(mesh);
        const app::DrawingPreparation prepared = app::prepare_for_drawing(mesh, rows, 40.0f);
        CHECK(prepared.units.identity() == (scale == 1.0f));
        const PositionBounds box = position_bounds(mesh.positions);
        CHECK(prepared.box.lo == box.lo);
        CHECK(prepared.box.hi == box.hi);
        const SplitMesh split = split_at_creases(std::move(mesh), prepared.creases.creases, &rows);
        REQUIRE(!split.copied_from.empty());  // fandisk has creases: the split copied vertices
        const render::BoundingSphere given = render::bounding_sphere(split.mesh, prepared.box),
                                     found = render::bounding_sphere(split.mesh);
        CHECK(given.center == found.center);
        CHECK(given.radius == found.radius);
        CHECK(found.radius > 0.5f);  // drawing units: fandisk's size, or unit radius
    }
}

TEST_CASE("kappa render draws a mesh whose faces point inwards as it draws it the right way round", "[render][cli]") {
    const std::string dir = test::temp_dir();
    Mesh mesh = load_mesh(test::shared_mesh("fandisk.obj"));
    std::string obj;
    for (const glm::vec3& p : mesh.positions)
        obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    auto write = [&](const std::string& name, bool inwards) {
        std::string text = obj;
        for (const Face& f : mesh.faces) {
            const Face g = inwards ? Face(f[0], f[2], f[1]) : f;
            text += "f " + std::to_string(g[0] + 1) + " " + std::to_string(g[1] + 1) + " " + std::to_string(g[2] + 1) + "\n";
        }
        test::write_file(dir + "/" + name + ".obj", text);
        const auto r = test::run_command(kappa_render(dir + "/" + name + ".obj -o " + dir + "/" + name +
                                                      ".png --size 240x180 --lines contours,suggestive,creases"));
        REQUIRE(r.exit_code == 0);
        CHECK((r.output.find("faces point inwards") != std::string::npos) == inwards);
        return render::read_png(dir + "/" + name + ".png");
    };
    const render::Image outward = write("outward", false), inward = write("inward", true);
    CHECK(test::count_ink(outward) > 500);
    CHECK(test::largest_difference(outward, inward) <= test::kScreenMergeTolerance);
}

TEST_CASE("the bounding sphere's radius is the largest distance from the box centre, point by point",
          "[render][units]") {
    // render/camera/camera.cpp takes the distances in double, four points at a time in lanes: the same
    // bits as one at a time (glm::dot), whatever the point the largest is and however many points there are.
    for (const size_t n : {size_t(1), size_t(5), size_t(65536 + 6), size_t(140001)}) {
        for (size_t far = 0; far < std::min<size_t>(n, 9); ++far) {
            Mesh mesh;
            mesh.positions.resize(n);
            for (size_t v = 0; v < n; ++v)  // spread on a sphere of radius 1..2 about (3, -1, 2)
                mesh.positions[v] = glm::vec3(3, -1, 2) + (1.0f + float(v % 7) / 7.0f) *
                                                              glm::normalize(glm::vec3(std::sin(0.37f * v) + 0.1f,
                                                                                       std::cos(0.91f * v),
                                                                                       std::sin(1.3f * v + 1)));
            const size_t chosen = far * (n / 9);  // the farthest point, in each of the lanes' slots in turn
            mesh.positions[chosen] = glm::vec3(3, -1, 2) + glm::vec3(far % 3 == 0 ? 5.5f : 0.5f,
                                                                     far % 3 == 1 ? -5.5f : 0.5f,
                                                                     far % 3 == 2 ? 5.5f : 0.5f);
            const PositionBounds box = position_bounds(mesh.positions);
            double largest = 0;
            for (const glm::vec3& p : mesh.positions) {
                const glm::dvec3 d = glm::dvec3(p) - glm::dvec3(box.center());
                largest = std::max(largest, glm::dot(d, d));
            }
            CAPTURE(n, far, chosen);
            const render::BoundingSphere sphere = render::bounding_sphere(mesh, box);
            CHECK(sphere.center == box.center());
            CHECK(sphere.radius == (largest > 0 ? float(std::sqrt(largest)) : 1.0f));  // a point: radius 1
        }
    }
}
