// New fields sent to the GPU in slices (MeshBuffers::begin_upload, as the
// viewer lands a new view's fields): until the last slice every frame is
// the picture of the fields before, after it the picture of the new ones,
// bit for bit as if they had been uploaded in one go.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/mesh/default_model.h"
#include "geometry/surface_analysis.h"
#include "render/fields/field_upload.h"
#include "render/fields/mesh_buffers.h"

using namespace kappa;

namespace {

// Other fields for the same mesh: twice the curvature (lines move).
SurfaceFields with_curvature_doubled(SurfaceFields fields) {
    for (size_t v = 0; v < fields.k1.size(); ++v) fields.k1[v] *= 2.0f, fields.k2[v] *= 2.0f;
    return fields;
}

// From +z, the bounding sphere in view.
render::Camera front_camera(const render::BoundingSphere& bounds) {
    return render::Camera::look_at(bounds.center + glm::vec3(0, 0, 3.5f * bounds.radius), bounds.center, {0, 1, 0},
                                   30.0f);
}

}  // namespace

TEST_CASE("fields uploaded in slices are drawn whole, and only after the last slice", "[render][upload]") {
    const Mesh mesh = make_default_model();
    const SurfaceFields fields = compute_surface_fields(mesh);
    const float fs = feature_size(mesh, fields);
    // Other fields: the surface grown by 4% about its centre (the outline moves) and twice the curvature.
    Mesh grown = mesh;
    const render::BoundingSphere bounds = render::bounding_sphere(mesh);
    for (glm::vec3& p : grown.positions) p = bounds.center + 1.04f * (p - bounds.center);
    const SurfaceFields other = with_curvature_doubled(fields);

    const render::Camera camera = front_camera(bounds);
    render::RenderSettings settings;  // shading, contours, suggestive contours
    render::Renderer& renderer = test::renderer();
    auto picture = [&] { return render::render_to_image(renderer, camera, settings, 240, 200).pixels; };
    renderer.set_mesh(grown, other, fs);
    const auto other_picture = picture();
    renderer.set_mesh(mesh, fields, fs);
    const auto first_picture = picture();
    REQUIRE(other_picture != first_picture);

    const render::MeshBuffers& buffers = *renderer.mesh();
    const size_t total = mesh.vertex_count() * (sizeof(render::GpuVertex) + sizeof(glm::vec3));
    const size_t slice = total / 5 + 1;  // five slices
    auto prepared = [&](const Mesh& m, const SurfaceFields& f) {
        return render::prepare_field_upload(m, f, fs, {}, buffers.face_clusters());
    };
    // Lands `m`, `f` in slices, checking every frame in between; returns the calls made.
    auto land_in_slices = [&](const Mesh& m, const SurfaceFields& f, const std::vector<uint8_t>& before) {
        const uint64_t version = buffers.fields_version();
        const glm::vec3 position = buffers.cpu_mesh().positions[0];
        renderer.begin_field_upload(prepared(m, f));
        int calls = 0;
        while (true) {
            CHECK(renderer.field_upload_pending());
            const bool done = renderer.continue_field_upload(slice);
            ++calls;
            if (done) break;
            CHECK(buffers.fields_version() == version);
            CHECK(buffers.cpu_mesh().positions[0] == position);
            CHECK(picture() == before);
            REQUIRE(calls < 10);
        }
        CHECK_FALSE(renderer.field_upload_pending());
        CHECK(buffers.fields_version() != version);
        return calls;
    };

    CHECK(land_in_slices(grown, other, first_picture) == 5);
    CHECK(picture() == other_picture);
    size_t moved = 0;  // the CPU copy (CPU line passes, strokes) is the new one too
    for (size_t v = 0; v < mesh.vertex_count(); ++v)
        moved += buffers.cpu_mesh().positions[buffers.face_clusters().vertex_slot[v]] == grown.positions[v];
    CHECK(moved == mesh.vertex_count());
    // Back again, into the buffers the first fields were drawn from.
    CHECK(land_in_slices(mesh, fields, other_picture) == 5);
    CHECK(picture() == first_picture);

    // An upload in one go drops a pending one; so does a newer begin_upload.
    renderer.begin_field_upload(prepared(grown, other));
    CHECK_FALSE(renderer.continue_field_upload(slice));
    renderer.upload_fields(prepared(mesh, fields));
    CHECK_FALSE(renderer.field_upload_pending());
    CHECK(picture() == first_picture);
    renderer.begin_field_upload(prepared(mesh, fields));
    CHECK_FALSE(renderer.continue_field_upload(slice));
    renderer.begin_field_upload(prepared(grown, other));
    CHECK(renderer.continue_field_upload(total));
    CHECK(picture() == other_picture);
}

// A big mesh's first view in the viewer (MeshBuffers::InSlices): the triangles, records and
// positions go into new buffers a slice a call (then one call makes the spare buffers later
// views' fields go to), while the renderer draws the mesh it has; once the last call returns
// the buffers draw exactly what buffers made in one go draw.
TEST_CASE("a first view sent in slices draws what one upload draws", "[render][upload]") {
    const Mesh mesh = make_default_model();
    const SurfaceFields fields = compute_surface_fields(mesh);
    const float fs = feature_size(mesh, fields);
    const SurfaceFields other = with_curvature_doubled(fields);
    const render::Camera camera = front_camera(render::bounding_sphere(mesh));
    render::RenderSettings settings;
    settings.shading = render::Shading::None;  // lines alone: the curvature shows
    render::Renderer& renderer = test::renderer();
    auto picture = [&] { return render::render_to_image(renderer, camera, settings, 240, 200).pixels; };
    renderer.set_mesh(mesh, other, fs);
    const auto other_picture = picture();
    renderer.set_mesh(mesh, fields, fs);
    const auto whole_picture = picture();
    REQUIRE(other_picture != whole_picture);

    renderer.set_mesh(mesh, other, fs);  // what the window shows meanwhile
    auto landing = std::make_unique<render::MeshBuffers>(mesh, render::MeshBuffers::prepare(mesh, fields, fs),
                                                         render::MeshBuffers::InSlices{});
    const size_t total = mesh.face_count() * sizeof(Face) +
                         mesh.vertex_count() * (sizeof(render::GpuVertex) + sizeof(glm::vec3));
    const size_t slice = total / 7 + 1;  // seven slices
    int calls = 0;
    float progress = 0;
    while (true) {
        CHECK(landing->upload_pending());
        const bool done = landing->upload_step(slice);
        ++calls;
        if (done) break;
        if (calls < 7) {
            CHECK(landing->upload_progress() > progress);
            CHECK(landing->upload_progress() < 1.0f);
        } else {
            CHECK(landing->upload_progress() == 1.0f);  // every byte sent; the spare buffers next
        }
        progress = landing->upload_progress();
        CHECK(picture() == other_picture);  // the landing leaves the drawn mesh alone
        REQUIRE(calls < 10);
    }
    CHECK(calls == 8);  // and one making the spare buffers for later views
    CHECK(landing->upload_progress() == 1.0f);
    renderer.set_mesh(std::move(landing));
    CHECK(picture() == whole_picture);

    // New fields for a landing not yet done send what is left of it first.
    landing = std::make_unique<render::MeshBuffers>(mesh, render::MeshBuffers::prepare(mesh, fields, fs),
                                                    render::MeshBuffers::InSlices{});
    CHECK_FALSE(landing->upload_step(slice));
    landing->upload(render::prepare_field_upload(mesh, other, fs, {}, landing->face_clusters()));
    CHECK_FALSE(landing->upload_pending());
    renderer.set_mesh(std::move(landing));
    CHECK(picture() == other_picture);
}
