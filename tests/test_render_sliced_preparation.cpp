// A view's fields prepared in slices (MeshDrawing::prepare_view_slice, the
// web page's way: one thread, a few ms at a time) come to an end whatever the
// slice, and draw what the whole preparation draws. The first view's face
// clusters are one step: a slice that ran out of time after making them made
// them again at the next slice, so on bunny subdivided once (278k faces, its
// clustering longer than the page's 12 ms slices) the page never left
// "loading" (1878 slices and 50 s natively for 0.4 s of work, over 120 s in
// the browser).
#include "app/mesh_drawing.h"
#include "app/render_options.h"
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/subdivide.h"

#include "test_render_fixtures.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <cstdlib>

using namespace kappa;

TEST_CASE("a view prepared in slices of any length comes to an end and draws the whole preparation's picture",
          "[render][detail][slices]") {
    const Mesh mesh = subdivide_at_midpoints(load_mesh(test::shared_mesh("bunny.ply")));
    render::RenderSettings settings;  // detail 12 px, as kappa render and the page draw by default
    app::CameraOptions view;
    view.view = ViewAngles{30, 20};
    const glm::ivec2 size{400, 300};
    render::Renderer& renderer = test::renderer();

    app::MeshDrawing whole(mesh, settings, SmoothingOptions{});
    const render::Camera camera = app::make_camera(view, whole, size);
    const render::Image expected = whole.image(renderer, camera, settings, size);

    // Slices of 0.1 ms: each call does one step (a few thousand vertices or one stage; two when
    // a step is shorter than that), so the calls count the steps, whatever the machine: 230
    // here (2026-11-27). 2000 leaves a wide margin for other settings of the steps; a
    // preparation that starts a step again at every call never ends.
    app::MeshDrawing sliced(mesh, settings, SmoothingOptions{});
    REQUIRE(app::make_camera(view, sliced, size).view == camera.view);
    int calls = 0;
    while (!sliced.prepare_view_slice(renderer, camera, size, 1e-4) && calls < 2000) ++calls;
    INFO(calls << " calls");
    REQUIRE(calls < 2000);
    CHECK(calls > 10);  // it was cut into slices at all
    const render::Image got = sliced.image(renderer, camera, settings, size);
    REQUIRE(got.width == expected.width);
    REQUIRE(got.height == expected.height);
    // The same steps in the same order: the same fields, so the same pixels.
    size_t differing = 0;
    for (int y = 0; y < got.height; ++y)
        for (int x = 0; x < got.width; ++x) {
            const render::Rgba a = got.at(x, y), b = expected.at(x, y);
            differing += std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) > 0;
        }
    CHECK(differing == 0);
}
