// The compute path of the line passes (--line-extraction compute,
// render/lines/segment_buffer.h) runs each per-triangle family's own
// extraction functions (shaders/lines/*.glsl, shared with the geometry
// stage) in a compute pass and draws the appended segments with the CPU
// path's quad shader. So:
//   - against the geometry-shader path: the same segments and the same
//     fragment stage, so the same pixels up to float rounding in the two
//     compiled programs (a crossing or a visibility test flipping);
//   - against the CPU path: within the screen-merge bound of
//     test_render_cpu_lines.cpp (0.2 px and 1/64 opacity: under a quarter of
//     full ink a pixel), for every line family, on bunny and fandisk;
//   - a frame with more segments than the buffer holds is drawn again whole
//     (images) or drawn as far as it fits while the buffer grows (viewer).
// llvmpipe (Mesa 22.3) gives an OpenGL 4.5 core context, so all of this runs
// headless in CI.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"
#include "test_support.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/creases.h"
#include "render/fields/field_upload.h"
#include "geometry/surface_analysis.h"
#include "render/image/ink_agreement.h"
#include "render/lines/segment_buffer.h"

#include <cstdlib>
#include <string>
#include <vector>

using namespace kappa;

namespace {
// Every line family the compute path extracts, one selection each: the
// per-triangle ones, and the per-edge ones the mesh has (fandisk's creases,
// bunny's boundaries, with contours: ink on both paths).
std::vector<render::LineSelection> line_families(const std::string& mesh) {
    render::LineSelection contours_suggestive{true, true, false, false};
    render::LineSelection silhouette{false, false, false, false};
    silhouette.silhouette = true;
    render::LineSelection highlights{false, false, false, false};
    highlights.suggestive_highlights = highlights.dwkr = true;
    render::LineSelection ridges{false, false, false, false};
    ridges.ridges = ridges.valleys = true;
    render::LineSelection parabolic{false, false, false, false};
    parabolic.parabolic = parabolic.mean_zero = true;
    render::LineSelection view_ridges{false, false, false, false};
    view_ridges.apparent_ridges = view_ridges.principal_highlights = true;
    render::LineSelection levels{false, false, false, false};
    levels.isophotes = levels.topo = true;
    render::LineSelection edges{false, false, false, false};
    if (mesh == "fandisk.obj") edges.creases = true;
    else edges.contours = edges.boundaries = true;
    return {contours_suggestive, silhouette, highlights, ridges, parabolic, view_ridges, levels, edges};
}

struct ShapeUnderTest {
    Mesh mesh;  // split at its creases (--crease-angle auto), as kappa render draws it
    SurfaceFields fields;
    float fs;
    render::Camera camera;
    std::vector<glm::vec3> crease_points;  // render/fields/field_upload.h
};

ShapeUnderTest shared_shape(const std::string& name) {
    const Mesh input = load_mesh(test::shared_mesh(name));
    SplitMesh split = split_at_creases(input, find_creases(input, auto_crease_angle(input)));
    std::vector<glm::vec3> crease_points = render::crease_end_points(split);
    ShapeUnderTest t{std::move(split.mesh), {}, 0, {}, std::move(crease_points)};
    t.fields = compute_surface_fields(t.mesh);
    t.fs = feature_size(t.mesh, t.fields);
    t.camera = render::Camera::default_view(t.mesh, render::bounding_sphere(t.mesh), 30.0f, 4.0f / 3.0f);
    return t;
}

render::Image draw(const ShapeUnderTest& t, render::RenderSettings s, render::LineExtraction path) {
    s.line_extraction = path;
    render::Renderer& r = test::renderer();
    r.set_mesh(t.mesh, t.fields, t.fs);
    r.set_creases(t.crease_points);
    return render::render_to_image(r, t.camera, s, 640, 480);
}

}  // namespace

TEST_CASE("the headless context offers the compute line path, and auto keeps the CPU path on software GL",
          "[render][compute-lines]") {
    render::Renderer& r = test::renderer();
    REQUIRE(r.segment_buffer() != nullptr);  // llvmpipe: OpenGL 4.5 core
    render::RenderSettings s;
    s.line_extraction = render::LineExtraction::Compute;
    CHECK(r.line_path(s) == render::LineExtraction::Compute);
    s.line_extraction = render::LineExtraction::Gpu;
    CHECK(r.line_path(s) == render::LineExtraction::Gpu);
    s.line_extraction = render::LineExtraction::Auto;
    CHECK(r.line_path(s) == render::LineExtraction::Cpu);  // software GL
}

TEST_CASE("compute-shader and geometry-shader extraction draw the same pixels", "[render][compute-lines]") {
    for (const std::string name : {"bunny.ply", "fandisk.obj"}) {
        const ShapeUnderTest t = shared_shape(name);
        for (const render::LineSelection& lines : line_families(name)) {
            for (const bool hidden : {false, true}) {
                INFO(name << ", lines " << render::to_string(lines) << (hidden ? ", hidden lines" : ""));
                render::RenderSettings s = test::lines_only(lines);
                s.hidden_lines = hidden;
                const render::Image gs = draw(t, s, render::LineExtraction::Gpu);
                const render::Image cs = draw(t, s, render::LineExtraction::Compute);
                const size_t ink = test::count_ink(gs), differ = test::differing_pixels(gs, cs);
                INFO(ink << " ink pixels, " << differ << " pixels differ");
                CHECK(ink > 200);
                CHECK(double(differ) <= 0.001 * double(ink));
                CHECK(render::ink_within(gs, cs, 1.0f) > 0.999);
                CHECK(render::ink_within(cs, gs, 1.0f) > 0.999);
            }
        }
    }
}

TEST_CASE("compute-shader and CPU extraction draw the same image within the merge bound", "[render][compute-lines]") {
    for (const std::string name : {"bunny.ply", "fandisk.obj"}) {
        const ShapeUnderTest t = shared_shape(name);
        for (const render::LineSelection& lines : line_families(name)) {
            INFO(name << ", lines " << render::to_string(lines));
            const render::RenderSettings s = test::lines_only(lines);
            const render::Image cs = draw(t, s, render::LineExtraction::Compute);
            const render::Image cpu = draw(t, s, render::LineExtraction::Cpu);
            const size_t ink = test::count_ink(cs), differ = test::differing_pixels(cs, cpu);
            INFO(ink << " ink pixels, " << differ << " pixels differ");
            CHECK(ink > 200);
            CHECK(double(differ) < 0.02 * double(ink));
            CHECK(render::ink_within(cs, cpu, 1.0f) > 0.995);
            CHECK(render::ink_within(cpu, cs, 1.0f) > 0.995);
        }
    }
}

TEST_CASE("a frame with more segments than the buffer holds is drawn whole, and the buffer grows",
          "[render][compute-lines]") {
    const ShapeUnderTest t = shared_shape("bunny.ply");
    render::LineSelection lines{true, true, false, false};
    lines.isophotes = lines.topo = true;
    render::RenderSettings s = test::lines_only(lines);
    s.line_extraction = render::LineExtraction::Compute;
    render::Renderer& r = test::renderer();
    r.set_mesh(t.mesh, t.fields, t.fs);
    const render::Image reference = render::render_to_image(r, t.camera, s, 640, 480);
    const uint32_t needed = r.segment_buffer()->capacity();
    REQUIRE(test::count_ink(reference) > 2000);

    // Images: a buffer of 64 segments is grown and the frame drawn again at once.
    r.segment_buffer()->set_capacity(64);
    CHECK(test::largest_difference(render::render_to_image(r, t.camera, s, 640, 480), reference) == 0);
    CHECK(r.segment_buffer()->capacity() > 64);
    CHECK(r.segment_buffer()->capacity() <= needed);

    // A viewer's frames never wait: the first draws what fits (64 segments: far
    // less ink), the buffer grows from its count, and the next frame is whole.
    r.set_complete_frames(false);
    r.segment_buffer()->set_capacity(64);
    const render::Image partial = render::render_to_image(r, t.camera, s, 640, 480);
    const render::Image next = render::render_to_image(r, t.camera, s, 640, 480);
    r.set_complete_frames(true);
    CHECK(test::count_ink(partial) < test::count_ink(reference) / 2);
    CHECK(test::largest_difference(next, reference) == 0);
}
