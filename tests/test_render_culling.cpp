// Cluster culling of the contour pass (render/lines/cluster_culling.h) skips work,
// never lines: the image is the same with and without it. On software GL the
// lines are made on the CPU and merged on screen (render/lines/screen_merge.h),
// where a polyline cut at a culled cluster outside the view may merge its
// first segments inside the view from another point: those pixels move by
// at most the merge error (test::kScreenMergeTolerance), while a line lost
// to culling would change its pixels by its full ink.
// The other line passes skip the clusters outside the view and the entirely
// back-facing ones: the same lines but for a few pixels near contours.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"
#include "test_support.h"

#include "geometry/mesh/default_model.h"
#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/mesh/primitives.h"
#include "geometry/surface_analysis.h"
#include "geometry/culling/back_faces.h"
#include "render/surface/back_face_culling.h"
#include "render/lines/cluster_culling.h"
#include "render/camera/frame_params.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <iterator>

using namespace kappa;

namespace {

void check_same_with_and_without_culling(const Mesh& mesh, const std::string& name) {
    const SurfaceFields fields = compute_surface_fields(mesh);
    const float fs = feature_size(mesh, fields);
    const auto bounds = render::bounding_sphere(mesh);
    const float r = bounds.radius;
    struct View {
        glm::vec3 eye, target;
        float fov;
    };
    // Around the model, from above, and close up on the right rim with most
    // of the model outside the image.
    const glm::vec3 o(0);
    const View views[] = {{{0, 0, 3 * r}, o, 30.0f},
                          {{3 * r, 0.5f * r, 0}, o, 30.0f},
                          {{-2 * r, r, -2 * r}, o, 30.0f},
                          {{0, 3 * r, 0.1f * r}, o, 30.0f},
                          {{0.7f * r, 0, 2 * r}, {0.7f * r, 0, 0}, 15.0f}};
    render::LineSelection highlights{false, false, false}, dwkr{true, false, false};
    highlights.suggestive_highlights = true;
    dwkr.dwkr = true;
    for (const auto& lines : {render::LineSelection{true, true, false}, render::LineSelection{true, false, false},
                              render::LineSelection{false, true, false}, highlights, dwkr}) {
        for (const View& v : views) {
            const auto camera = render::Camera::look_at(bounds.center + v.eye, bounds.center + v.target, {0, 1, 0}, v.fov);
            auto s = test::lines_only(lines);
            // Many suggestive contours; alone, a threshold at which the bound on Dw kr culls too.
            s.sc_threshold = lines.contours ? 0.02f : 0.3f;
            s.cull_clusters = false;
            const auto all = test::render(mesh, fields, fs, camera, s, 320, 240);
            s.cull_clusters = true;
            const auto culled = test::render(mesh, fields, fs, camera, s, 320, 240);
            test::maybe_save(culled, name + "_culled");
            INFO(name << ", eye " << v.eye.x << "," << v.eye.y << "," << v.eye.z << ", lines "
                      << render::to_string(lines));
            CHECK(test::count_ink(all) > 100);
            CHECK(test::largest_difference(culled, all) <= test::kScreenMergeTolerance);
        }
    }
}

}  // namespace

TEST_CASE("cluster culling gives the same lines as drawing every triangle", "[render][culling]") {
    SECTION("bunny") { check_same_with_and_without_culling(load_mesh(test::shared_mesh("bunny.ply")), "bunny"); }
    SECTION("built-in model") { check_same_with_and_without_culling(make_default_model(), "default"); }
}

TEST_CASE("culling back-facing clusters in the other line passes changes only pixels near contours, the rest of their "
          "culling none",
          "[render][culling]") {
    const auto bounds = test::upload_shared_bunny();
    const auto camera = render::Camera::look_at(bounds.center + glm::vec3(-2, 1, -2) * bounds.radius, bounds.center,
                                                {0, 1, 0}, 30.0f);
    auto draw = [&](const render::RenderSettings& s) {
        return render::render_to_image(test::renderer(), camera, s, 320, 240);
    };
    render::LineSelection lines{false, false, false, false, true, true, true, true, true, true};
    lines.apparent_ridges = lines.principal_highlights = lines.dwkr = true;
    auto s = test::lines_only(lines);
    s.cull_clusters = false;
    const auto all = draw(s);
    s.cull_clusters = true;
    const auto culled = draw(s);
    size_t differ = 0;
    for (int y = 0; y < all.height; ++y)
        for (int x = 0; x < all.width; ++x) differ += test::is_ink(all.at(x, y)) != test::is_ink(culled.at(x, y));
    INFO("ink " << test::count_ink(all) << ", pixels whose ink differs " << differ);
    CHECK(test::count_ink(all) > 2000);
    CHECK(differ < test::count_ink(all) / 100);

    // With hidden lines nothing back-facing is skipped, and the passes' own
    // culling (no level in a cluster's range of n.l or heights, no sign change
    // of K or H, |kmax| or the highlight strength below the threshold) is exact.
    render::LineSelection levels{false, false, false, false, true, true, true, true, true, true};
    levels.principal_highlights = true;
    s = test::lines_only(levels);
    s.hidden_lines = true;
    s.isophote_count = 8;
    s.topo_count = 30;
    s.cull_clusters = false;
    const auto every = draw(s);
    s.cull_clusters = true;
    const auto skipped = draw(s);
    CHECK(test::count_ink(every) > 2000);
    CHECK(skipped.pixels == every.pixels);
}

TEST_CASE("cluster culling skips most of a sphere's triangles", "[render][culling]") {
    const Mesh sphere = make_icosphere(1.0f, 6);
    const SurfaceFields fields = compute_surface_fields(sphere);
    const render::MeshClusters clusters = render::make_mesh_clusters(sphere, fields, cluster_faces(sphere, 256), 1.0f);
    const auto bounds = render::bounding_sphere(sphere);
    const auto camera = render::Camera::look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 40.0f);
    const auto frame = render::FrameParams::make(camera, bounds, 400, 400);
    auto drawn = [&](bool contours, bool suggestive) {
        size_t faces = 0;
        for (const auto& run : render::contour_pass_runs(clusters, frame, contours, suggestive, 0.05f, 3.0f)) faces += run.count;
        return double(faces) / double(sphere.face_count());
    };
    // A sphere is elliptic everywhere: no suggestive contours, so only the
    // clusters along the contour (a band around the rim) are drawn.
    CHECK(drawn(true, true) < 0.3);
    CHECK(drawn(false, true) == 0.0);
    CHECK(drawn(true, false) > 0.0);
}

// MeshBuffers stores the faces cluster by cluster and the vertices in their
// order of first use (FaceClusters::vertex_order): its CPU copy, which the
// CPU line pass and strokes read, must still be the same surface with the
// same fields at every corner of every face.
TEST_CASE("the uploaded mesh is the input's faces and fields, reordered", "[render][clusters]") {
    Mesh mesh = make_torus(1.0f, 0.4f, 40, 20);
    mesh.positions.push_back(glm::vec3(9, 9, 9));  // a vertex no face uses
    const SurfaceFields fields = compute_surface_fields(mesh);
    test::renderer().set_mesh(mesh, fields, feature_size(mesh, fields));
    const render::MeshBuffers& gpu = *test::renderer().mesh();
    const FaceClusters& clusters = gpu.face_clusters();
    const Mesh& copy = gpu.cpu_mesh();
    REQUIRE(copy.face_count() == mesh.face_count());
    REQUIRE(copy.vertex_count() == mesh.vertex_count());
    size_t wrong_corners = 0, reordered = 0;
    for (size_t i = 0; i < copy.face_count(); ++i)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = copy.faces[i][k], original = mesh.faces[clusters.face_order[i]][k];
            reordered += v != original;
            wrong_corners += copy.positions[v] != mesh.positions[original] ||
                             gpu.cpu_fields().k1[v] != fields.k1[original] ||
                             gpu.cpu_fields().d1[v] != fields.d1[original] ||
                             gpu.cpu_fields().dcurv[v] != fields.dcurv[original];
        }
    CHECK(wrong_corners == 0);
    CHECK(reordered > 0);  // the torus's own numbering is not the order of first use
    // Every vertex kept, the unused one too.
    CHECK(copy.positions[clusters.vertex_order.size() - 1] == glm::vec3(9, 9, 9));
}

// The surface pass culls back faces except where a hole is seen
// (geometry/culling/back_faces.h, render/surface/back_face_culling.h): the depth it leaves,
// which every line's visibility is tested against, is the depth of drawing
// every face, in views into the holes of a scan, from below, close up and
// mirrored, with and without MSAA; and white paper (positions only) leaves
// the depth Lambert does.
TEST_CASE("culled back faces leave the depth of every face drawn", "[render][clusters]") {
    const render::BoundingSphere bounds = test::upload_shared_bunny();
    render::Renderer& r = test::renderer();
    const glm::vec3 c = bounds.center;
    const float d = 2.5f * bounds.radius;
    struct View {
        glm::vec3 eye;
        bool mirrored;
    };
    const View views[] = {{c + glm::vec3(0, 0, d), false},               // front
                          {c + glm::vec3(0.3f, -1.0f, 0.2f) * d, false},  // from below: into the holes
                          {c + glm::vec3(-0.2f, -0.6f, 0.7f) * d, false},
                          {c + glm::vec3(0.1f, -0.25f, 0.45f) * d, false},  // close up, the base's holes large
                          {c + glm::vec3(0.3f, -1.0f, 0.2f) * d, true}};
    size_t culled_views = 0;
    for (const bool msaa : {false, true})
    for (const View& v : views) {
        render::Camera camera = render::Camera::look_at(v.eye, c, glm::vec3(0, 1, 0), 30.0f);
        if (v.mirrored) camera.view = camera.view * glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1));
        render::RenderSettings s = test::lines_only({false, false, false, false});
        s.shading = render::Shading::Lambert;
        s.msaa = msaa;
        // Grey: white paper on white would not be multisampled (surface_is_background).
        s.background = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
        const auto frame = render::FrameParams::make(camera, r.mesh()->bounds(), 400, 300);
        culled_views += render::back_face_culling(r.mesh()->back_faces(), r.mesh()->bounds(), r.mesh()->clusters(),
                                                  frame).cull;
        r.set_back_face_culling(false);
        r.render_offscreen(camera, s, 400, 300);
        const std::vector<float> every = r.surface_depth();
        r.set_back_face_culling(true);
        r.render_offscreen(camera, s, 400, 300);
        const std::vector<float> culled = r.surface_depth();
        // Paper draws from a buffer of positions alone (MeshBuffers::draw_triangle_positions).
        s.shading = render::Shading::None;
        r.render_offscreen(camera, s, 400, 300);
        const std::vector<float> paper = r.surface_depth();
        r.set_back_face_culling(false);
        r.render_offscreen(camera, s, 400, 300);
        const std::vector<float> paper_every = r.surface_depth();
        r.set_back_face_culling(true);
        // Paper reads a buffer of positions of its own; a colour map reads the
        // whole vertex records.
        s.colormap = render::ColorMap::Mean;
        r.render_offscreen(camera, s, 400, 300);
        const std::vector<float> mapped = r.surface_depth();
        s.colormap = render::ColorMap::None;
        size_t covered = 0, differ = 0, paper_differs = 0;
        float largest = 0;
        for (size_t i = 0; i < every.size(); ++i) {
            covered += every[i] < 1.0f;
            differ += culled[i] != every[i];
            largest = std::max(largest, std::fabs(culled[i] - every[i]));
            paper_differs += paper[i] != culled[i] || paper_every[i] != every[i] || mapped[i] != culled[i];
        }
        INFO("eye " << v.eye.x << " " << v.eye.y << " " << v.eye.z << (v.mirrored ? " mirrored" : "")
                    << (msaa ? ", 4x MSAA" : "") << ": "
                    << covered << " pixels covered, " << differ << " differ");
        CHECK(covered > 10000);
        // A pixel centre on a contour edge, between a front and a back
        // triangle, may fall to either once the rasteriser has snapped the
        // vertices to its sub-pixel grid: measured 1 pixel of 69,000 in these
        // views, its depth 5e-5 apart.
        CHECK(differ * 10000 <= covered);
        CHECK(largest < 1e-3f);
        CHECK(paper_differs == 0);
    }
    CHECK(culled_views == 2 * std::size(views));  // the culling was on in every view
}

TEST_CASE("back faces are not culled with the eye inside the bounding sphere or on open sheets", "[render][clusters]") {
    const Mesh torus = make_torus(1.0f, 0.3f, 48, 24);
    const render::BoundingSphere bounds = render::bounding_sphere(torus);
    const BackFaceVisibility visibility = back_face_visibility(torus);
    const render::MeshClusters none;
    auto culling_from = [&](glm::vec3 eye) {
        const render::Camera camera = render::Camera::look_at(eye, glm::vec3(0), glm::vec3(0, 1, 0), 30.0f);
        return render::back_face_culling(visibility, bounds, none, render::FrameParams::make(camera, bounds, 400, 300));
    };
    CHECK(culling_from(glm::vec3(0, 0, 4)).cull);
    CHECK(!culling_from(glm::vec3(0, 0.1f, 0.5f)).cull);  // in the hole of the torus, inside its bounding sphere
    const render::Camera camera = render::Camera::look_at(glm::vec3(0, 0, 4), glm::vec3(0), glm::vec3(0, 1, 0), 30.0f);
    const Mesh grid = make_grid(2.0f, 10);
    CHECK(!render::back_face_culling(back_face_visibility(grid), render::bounding_sphere(grid), none,
                                     render::FrameParams::make(camera, render::bounding_sphere(grid), 400, 300))
               .cull);
}

TEST_CASE("white paper on white is drawn once a pixel: the picture of a multisampled surface, for a quarter of the "
          "samples",
          "[render][msaa]") {
    const auto camera = render::Camera::framing(test::upload_shared_bunny(), 30.0f, 4.0f / 3.0f);
    auto draw = [&](const render::RenderSettings& s) {
        return render::render_to_image(test::renderer(), camera, s, 400, 300);
    };
    render::RenderSettings s = test::lines_only({true, true, false});
    s.msaa = true;
    const auto white = draw(s);
    s.msaa = false;
    CHECK(test::largest_difference(draw(s), white) == 0);
    // Off-white (blue 254): the surface pass is multisampled as before.
    s.msaa = true;
    s.background = glm::vec4(1.0f, 1.0f, 254.0f / 255.0f, 1.0f);
    const auto multisampled = draw(s);
    size_t differ = 0, off_white = 0;
    for (int y = 0; y < white.height; ++y)
        for (int x = 0; x < white.width; ++x) {
            const render::Rgba a = white.at(x, y), b = multisampled.at(x, y);
            differ += std::abs(a.r - b.r) > 2 || std::abs(a.g - b.g) > 2;
            off_white += b.b == 254 && b.r == 255;
        }
    const size_t ink = test::count_ink(white);
    INFO(ink << " ink pixels, " << differ << " differ");
    CHECK(ink > 1000);
    CHECK(off_white > 10000);  // the other picture really was drawn on off-white
    // The lines' visibility reads the surface depth: multisampled, the depth of
    // one sample off the pixel centre, so a line end at an occluding contour
    // may gain or lose a pixel (measured 37 of 10,400 ink pixels at 1024x768).
    CHECK(differ * 100 <= ink);
}
