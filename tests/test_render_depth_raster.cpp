// The surface depth drawn on the CPU (render/surface/depth_raster.h: white paper under
// CPU-drawn lines on software GL) is the GL's: the same pixels covered but at
// the outline, where a pixel centre lies within rounding of an edge, and the
// same depth within float rounding elsewhere; in views where back faces show
// through holes, from inside the bounding sphere (every face drawn, faces
// cut by the near plane) and with culling off.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"
#include "test_support.h"

#include "geometry/parallel/parallel.h"

#include <algorithm>
#include <cmath>

using namespace kappa;

TEST_CASE("the surface depth drawn on the CPU is the GL's", "[render][depth-raster]") {
    const auto b = test::upload_shared_bunny();
    const float r = b.radius;
    struct View {
        glm::vec3 eye, target;
        bool cull;
    };
    const View views[] = {{b.center + glm::vec3(0.3f, 0.4f, 2.5f) * r, b.center, true},
                          {b.center + glm::vec3(0.4f, -2.5f, 0.6f) * r, b.center, true},     // the holes in its base
                          {b.center + glm::vec3(0.1f, 0.2f, 0.55f) * r, b.center, true},     // inside the sphere, near plane cuts
                          {b.center + glm::vec3(-2.0f, 0.5f, -1.5f) * r, b.center, false}};  // every face
    render::Renderer& renderer = test::renderer();
    const render::RenderSettings s = test::lines_only(render::LineSelection{true, true, false, false});
    const int w = 320, h = 240;
    for (const View& v : views) {
        const auto camera = render::Camera::look_at(v.eye, v.target, {0, 1, 0}, 40.0f);
        renderer.set_back_face_culling(v.cull);
        renderer.set_cpu_surface_depth(false);
        render::render_to_image(renderer, camera, s, w, h);
        const std::vector<float> gl = renderer.surface_depth();
        renderer.set_cpu_surface_depth(true);
        render::render_to_image(renderer, camera, s, w, h);
        const std::vector<float> cpu = renderer.surface_depth();
        // Ranges of faces into buffers merged by the minimum: the same depths on one thread.
        set_thread_count(1);
        render::render_to_image(renderer, camera, s, w, h);
        CHECK(renderer.surface_depth() == cpu);
        set_thread_count(0);
        REQUIRE(gl.size() == cpu.size());
        // Covered by one only, or at different depths: a pixel centre within rounding of an edge of the
        // outline (llvmpipe snaps vertices to 1/256 pixel), where the depth jumps to what lies behind.
        size_t covered = 0, differ = 0, unexplained = 0;
        float largest = 0;  // elsewhere
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t i = size_t(y) * w + x;
                covered += gl[i] < 1.0f;
                const float d = std::fabs(gl[i] - cpu[i]);
                if (d <= 1e-5f) continue;
                ++differ;
                float jump = 0;  // the largest step of the GL's depth to a neighbour
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, h - 1);
                        jump = std::max(jump, std::fabs(gl[size_t(ny) * w + nx] - gl[i]));
                    }
                if (jump < 0.5f * d) ++unexplained, largest = std::max(largest, d);
            }
        INFO("eye " << v.eye.x << "," << v.eye.y << "," << v.eye.z << ": " << covered << " covered, " << differ
                    << " differ by more than 1e-5, " << unexplained << " of them not at a depth jump (largest "
                    << largest << ")");
        CHECK(covered > 5000);
        CHECK(differ < covered / 500);
        CHECK(unexplained == 0);
    }
    renderer.set_back_face_culling(true);
}
