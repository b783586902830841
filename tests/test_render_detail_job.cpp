// The detail fields in steps (render/fields/detail_fields_job.h), as the
// browser page prepares them between frames: cut into small steps, the job
// gives the same bits as detail_fields in one go, on the paths a view can
// take (levels only; the raw C tested and blended in, or refused; a noisy
// mesh drawn denoised), and a job dropped half-way leaves the source as good
// as it found it; the upload's CPU half likewise.
#include "analytic_curvature.h"

#include "geometry/mesh/default_model.h"
#include "geometry/mesh/primitives.h"
#include "geometry/scale/scale_space.h"
#include "geometry/surface_analysis.h"
#include "geometry/culling/face_clusters.h"
#include "render/fields/detail_fields_job.h"
#include "render/fields/field_upload.h"

#include <catch2/catch.hpp>

#include <cstring>

using namespace kappa;

namespace {

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

template <typename T>
bool same_bits(const UninitializedArray<T>& a, const UninitializedArray<T>& b) {
    return a.size() == b.size() && (a.size() == 0 || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same_bits(const render::DetailFields& a, const render::DetailFields& b) {
    const SurfaceFields &f = a.fields, &g = b.fields;
    return same_bits(a.mesh.positions, b.mesh.positions) && same_bits(a.mesh.faces, b.mesh.faces) &&
           same_bits(a.fine_normals, b.fine_normals) && same_bits(f.normals, g.normals) && same_bits(f.k1, g.k1) &&
           same_bits(f.k2, g.k2) && same_bits(f.d1, g.d1) && same_bits(f.d2, g.d2) && same_bits(f.dcurv, g.dcurv) &&
           same_bits(f.flags, g.flags) && std::memcmp(&a.feature_size, &b.feature_size, sizeof(float)) == 0;
}

// Per-vertex scales from `lo` to `hi` mean edges across the mesh (along x), as a
// slanted view gives: several levels, and below `1.5` edges the raw estimate.
render::ViewScales slanted_scales(const Mesh& mesh, float lo, float hi) {
    const float edge = mean_edge_length(mesh);
    render::ViewScales s;
    for (const glm::vec3& p : mesh.positions) {
        const float t = glm::clamp(0.5f * (p.x + 1.0f), 0.0f, 1.0f);
        s.sigma.push_back(edge * (lo + t * (hi - lo)));
    }
    s.fine = s.sigma;
    for (float& f : s.fine) f *= 0.5f;
    return s;
}

struct Case {
    const char* name;
    Mesh mesh;
    float lo, hi;  // mean edges
    bool denoised;
    render::DetailSource::Raw raw;  // what the view finds out about the raw C
};

}  // namespace

TEST_CASE("The detail fields prepared in small steps are the same bits as in one go", "[render][detail]") {
    Mesh noisy = make_default_model_from(make_icosphere(1.0f, 5));
    add_normal_noise(noisy, 0.3f * mean_edge_length(noisy), 7);
    using Raw = render::DetailSource::Raw;
    Case cases[] = {
        {"regular torus, raw C blended in", test::analytic_torus(1, 0.4, 120, 60).mesh, 0.75f, 12.0f, false, Raw::Consistent},
        {"jittered torus, raw C refused", test::analytic_torus(1, 0.4, 120, 60, 0.3, 5).mesh, 0.75f, 12.0f, false, Raw::Inconsistent},
        {"built-in shape, levels only", make_default_model(), 3.0f, 20.0f, false, Raw::Unknown},
        {"noisy shape, drawn denoised", std::move(noisy), 0.75f, 12.0f, true, Raw::Unknown},
    };
    for (Case& c : cases) {
        INFO(c.name);
        const SurfaceFields raw = compute_surface_fields(c.mesh);
        const render::ViewScales scales = slanted_scales(c.mesh, c.lo, c.hi);
        render::DetailSource once = render::make_detail_source(c.mesh, raw);
        CHECK((once.denoised_at > 0) == c.denoised);
        const render::DetailFields reference = render::detail_fields(c.mesh, once, raw, scales);

        // Cut into steps of 500 vertices (or clusters), after a job for another
        // view was dropped half-way on the same source.
        render::DetailSource stepped = render::make_detail_source(c.mesh, raw);
        {
            render::DetailFieldsJob dropped(c.mesh, stepped, raw, slanted_scales(c.mesh, c.hi, 4 * c.hi), 500);
            for (int i = 0; i < 7 && !dropped.done(); ++i) dropped.step();
            CHECK_FALSE(dropped.done());
        }
        render::DetailFieldsJob job(c.mesh, stepped, raw, scales, 500);
        size_t steps = 0;
        while (!job.done()) job.step(), ++steps;
        INFO(steps << " steps for " << c.mesh.vertex_count() << " vertices");
        CHECK(steps > 2 * c.mesh.vertex_count() / 500);  // two blends, each cut in pieces
        CHECK(stepped.raw == once.raw);
        CHECK(once.raw == c.raw);
        CHECK(same_bits(job.take(), reference));
    }
}

TEST_CASE("A detail fields job given no time runs one step a call", "[render][detail]") {
    const Mesh mesh = make_default_model();
    const SurfaceFields raw = compute_surface_fields(mesh);
    render::DetailSource source = render::make_detail_source(mesh, raw);
    render::DetailFieldsJob job(mesh, source, raw, slanted_scales(mesh, 3.0f, 20.0f), 500);
    // No time at all: one step a call, and the job gets done.
    size_t calls = 0;
    while (!job.run_for(0.0)) ++calls;
    CHECK(calls > 2 * mesh.vertex_count() / 500);
    CHECK(job.done());
}

// The CPU half of an upload (render/fields/field_upload.h) in small steps: the
// same records, colour-map ranges and cluster bounds.
TEST_CASE("The fields' upload prepared in small steps is the same bits as in one go", "[render][detail]") {
    const Mesh mesh = make_default_model();
    const SurfaceFields raw = compute_surface_fields(mesh);
    render::DetailSource source = render::make_detail_source(mesh, raw);
    const render::DetailFields d = render::detail_fields(mesh, source, raw, slanted_scales(mesh, 3.0f, 20.0f));
    const FaceClusters clusters = cluster_faces(mesh, 256);
    const render::FieldUpload once =
        render::prepare_field_upload(d.mesh, d.fields, d.feature_size, d.fine_normals, clusters);
    render::FieldUploadSteps steps(d.mesh, d.fields, d.feature_size, d.fine_normals, clusters, 500);
    size_t n = 0;
    while (!steps.done()) steps.step(), ++n;
    const render::FieldUpload stepped = steps.take();
    CHECK(n > mesh.vertex_count() / 500);
    CHECK(same_bits(stepped.vertices, once.vertices));
    // The CPU copy: the records' values, in their order.
    const render::FieldCopy& c = stepped.copy;
    CHECK(same_bits(c.positions, once.copy.positions));
    CHECK(same_bits(c.fine_normals, once.copy.fine_normals));
    CHECK(same_bits(c.fields.dcurv, once.copy.fields.dcurv));
    REQUIRE(c.positions.size() == mesh.vertex_count());
    REQUIRE(c.fields.k2.size() == mesh.vertex_count());
    size_t mismatched = 0;
    for (size_t v = 0; v < mesh.vertex_count(); ++v) {
        const size_t i = clusters.vertex_slot[v];
        const render::GpuVertex& r = once.vertices[i];
        mismatched += c.positions[i] != d.mesh.positions[v] || c.fields.normals[i] != r.normal ||
                      c.fields.d1[i] != r.d1 || c.fields.d2[i] != r.d2 || c.fields.k1[i] != r.curv.x ||
                      c.fields.k2[i] != r.curv.y || c.fields.dcurv[i] != r.dcurv ||
                      c.fine_normals[i] != r.fine_normal ||
                      c.fields.unreliable(i) != d.fields.unreliable(v);
    }
    CHECK(mismatched == 0);
    const render::MeshClusters &a = stepped.clusters, &b = once.clusters;
    CHECK(same_bits(a.bounds, b.bounds));
    CHECK(same_bits(a.fine_bounds, b.fine_bounds));
    CHECK(same_bits(a.first_face, b.first_face));
    CHECK(same_bits(a.may_have_suggestive, b.may_have_suggestive));
    CHECK(same_bits(a.max_strength, b.max_strength));
    CHECK(same_bits(a.may_have_parabolic, b.may_have_parabolic));
    CHECK(same_bits(a.may_have_mean_zero, b.may_have_mean_zero));
    CHECK(same_bits(a.max_kmax, b.max_kmax));
    CHECK(same_bits(a.max_highlight, b.max_highlight));
}
