// The line passes with their lines made on the CPU (render/lines/cpu_lines.h, the
// default on software GL) draw what the geometry-shader passes draw: the same
// triangles are cut by the same tests and the segments drawn by the same
// fragment shader. The CPU path merges consecutive segments on screen
// (render/lines/screen_merge.h) within 0.2 px and 1/64 opacity; the box-filtered
// coverage moves by at most the distance the centre line moves, so a pixel
// changes by at most 0.2 + 1/64 < 0.25 of full ink, except in the few
// pixels where float rounding moves a crossing or a visibility test flips.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"
#include "test_support.h"

#include "geometry/mesh/default_model.h"
#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/primitives.h"
#include "geometry/surface_analysis.h"
#include "render/image/ink_agreement.h"

#include <cstdlib>
#include <string>

using namespace kappa;

TEST_CASE("CPU and geometry-shader extraction of lines draw the same image", "[render][cpu-lines]") {
    for (const std::string& name : {std::string(), std::string("bunny.ply")}) {
        const Mesh mesh = name.empty() ? make_default_model() : load_mesh(test::shared_mesh(name));
        const SurfaceFields fields = compute_surface_fields(mesh);
        const float fs = feature_size(mesh, fields);
        const auto camera = render::Camera::default_view(mesh, render::bounding_sphere(mesh), 30.0f, 4.0f / 3.0f);
        render::LineSelection contours_suggestive{true, true, false, false};
        render::LineSelection silhouette{false, false, false, false};
        silhouette.silhouette = true;
        render::LineSelection highlights{false, false, false, false};
        highlights.suggestive_highlights = highlights.dwkr = true;
        render::LineSelection curvature{false, false, false, false};
        curvature.ridges = curvature.valleys = curvature.parabolic = curvature.mean_zero = true;
        render::LineSelection view_ridges{false, false, false, false};
        view_ridges.apparent_ridges = view_ridges.principal_highlights = true;
        render::LineSelection levels{false, false, false, false};
        levels.isophotes = levels.topo = true;
        const render::LineSelection boundaries{true, false, true, false};  // bunny's holes (contours: ink on both)
        for (const render::LineSelection& lines :
             {contours_suggestive, silhouette, highlights, curvature, view_ridges, levels, boundaries}) {
            INFO((name.empty() ? "built-in" : name) << ", lines " << render::to_string(lines));
            render::RenderSettings s = test::lines_only(lines);
            s.line_extraction = render::LineExtraction::Gpu;
            const render::Image gpu = test::render(mesh, fields, fs, camera, s, 640, 480);
            s.line_extraction = render::LineExtraction::Cpu;
            const render::Image cpu = test::render(mesh, fields, fs, camera, s, 640, 480);
            const size_t ink = test::count_ink(gpu), differ = test::differing_pixels(gpu, cpu);
            INFO(ink << " ink pixels, " << differ << " pixels differ");
            CHECK(ink > 200);
            CHECK(double(differ) < 0.02 * double(ink));
            CHECK(render::ink_within(gpu, cpu, 1.0f) > 0.995);
            CHECK(render::ink_within(cpu, gpu, 1.0f) > 0.995);
        }
    }
}

// Ridges, valleys, parabolic, H = 0 and topographic lines are extracted once
// per block of faces and kept between frames (render/lines/view_independent_lines.h):
// a view drawn after others is the same image as drawn first, and new fields
// or new settings of those types are not drawn with the old lines.
TEST_CASE("kept view-independent lines draw what a first frame draws", "[render][cpu-lines]") {
    const Mesh mesh = load_mesh(test::shared_mesh("bunny.ply"));
    const SurfaceFields fields = compute_surface_fields(mesh);
    const float fs = feature_size(mesh, fields);
    const auto bounds = render::bounding_sphere(mesh);
    const float r = bounds.radius;
    const auto front = render::Camera::look_at(bounds.center + glm::vec3(0, 0, 3 * r), bounds.center, {0, 1, 0}, 30.0f);
    const auto side = render::Camera::look_at(bounds.center + glm::vec3(3 * r, r, 0), bounds.center, {0, 1, 0}, 30.0f);
    render::LineSelection lines{false, false, false, false};
    lines.ridges = lines.valleys = lines.parabolic = lines.mean_zero = lines.topo = true;
    render::RenderSettings s = test::lines_only(lines);
    s.line_extraction = render::LineExtraction::Cpu;
    render::Renderer& renderer = test::renderer();
    auto first_frame = [&](const SurfaceFields& f, const render::RenderSettings& settings) {
        renderer.set_mesh(mesh, f, fs);  // new buffers: nothing kept
        return render::render_to_image(renderer, front, settings, 320, 240);
    };

    renderer.set_mesh(mesh, fields, fs);
    render::render_to_image(renderer, side, s, 320, 240);
    const render::Image after_side = render::render_to_image(renderer, front, s, 320, 240);
    const render::Image first = first_frame(fields, s);
    CHECK(test::count_ink(first) > 1000);
    CHECK(after_side.pixels == first.pixels);

    // Other thresholds and levels, after the lines of `s` were kept.
    render::RenderSettings other = s;
    other.rv_threshold = 3.0f, other.topo_count = 7, other.fade = false;
    const render::Image changed = render::render_to_image(renderer, front, other, 320, 240);
    CHECK(changed.pixels != first.pixels);
    CHECK(changed.pixels == first_frame(fields, other).pixels);

    // New fields for the same buffers (as a new --detail scale uploads).
    SurfaceFields doubled = fields;
    for (size_t v = 0; v < doubled.k1.size(); ++v) doubled.k1[v] *= 2.0f, doubled.k2[v] *= 2.0f;
    renderer.set_mesh(mesh, fields, fs);
    render::render_to_image(renderer, front, s, 320, 240);
    renderer.update_fields(mesh, doubled, fs);
    const render::Image updated = render::render_to_image(renderer, front, s, 320, 240);
    CHECK(updated.pixels != first.pixels);
    CHECK(updated.pixels == first_frame(doubled, s).pixels);
}

// Open boundaries: drawn by the CPU line pass on software GL (with the other
// kinds, no GL pass of their own), as the GL pass draws them: a grid's square
// outline seen at a slant, and bunny.ply's holes seen from below (partly
// hidden by the rest of the base).
TEST_CASE("the CPU line pass draws open boundaries as the GL pass does", "[render][cpu-lines]") {
    const Mesh grid = make_grid(1.0f, 40), bunny = load_mesh(test::shared_mesh("bunny.ply"));
    for (const Mesh* mesh : {&grid, &bunny}) {
        const SurfaceFields fields = compute_surface_fields(*mesh);
        const float fs = feature_size(*mesh, fields);
        const auto b = render::bounding_sphere(*mesh);
        const glm::vec3 from = mesh == &grid ? glm::vec3(0.4f, -1.0f, 2.0f) : glm::vec3(0.3f, -2.5f, 1.0f);
        const auto camera = render::Camera::look_at(b.center + from * b.radius, b.center, {0, 0, 1}, 35.0f);
        render::RenderSettings s = test::lines_only(render::LineSelection{false, false, true, false});
        s.line_extraction = render::LineExtraction::Gpu;
        const render::Image gpu = test::render(*mesh, fields, fs, camera, s, 400, 300);
        s.line_extraction = render::LineExtraction::Cpu;
        const render::Image cpu = test::render(*mesh, fields, fs, camera, s, 400, 300);
        test::maybe_save(cpu, mesh == &grid ? "boundaries_grid" : "boundaries_bunny");
        const size_t ink = test::count_ink(gpu);
        INFO((mesh == &grid ? "grid" : "bunny") << ": " << ink << " ink pixels, CPU " << test::count_ink(cpu));
        CHECK(ink > (mesh == &grid ? 1000u : 100u));
        CHECK(double(test::differing_pixels(gpu, cpu)) < 0.02 * double(ink));
        CHECK(render::ink_within(gpu, cpu, 1.0f) > 0.995);
        CHECK(render::ink_within(cpu, gpu, 1.0f) > 0.995);
    }
}
