#include "mesh_drawing.h"

#include "mesh_source.h"
#include "render_options.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/lines/line_extraction.h"
#include "geometry/parallel/parallel.h"
#include "geometry/scale/denoise.h"
#include "render/fields/field_upload.h"
#include "render/image/image_writer.h"
#include "render/vector/vector_view.h"

#include <chrono>
#include <limits>
#include <stdexcept>

namespace kappa::app {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

MeshDrawing::MeshDrawing(Mesh input, const render::RenderSettings& settings, const SmoothingOptions& smoothing,
                         const ProgressFn& progress)
    : MeshDrawing(std::move(input), settings, smoothing, InSteps{}) {
    progress_ = progress;
    while (!open_step()) {
    }
}

MeshDrawing::MeshDrawing(Mesh input, const render::RenderSettings& settings, const SmoothingOptions& smoothing,
                         InSteps)
    : settings_(settings), smoothing_(smoothing), input_(std::move(input)) {}

bool MeshDrawing::open_step() {
    switch (opened_steps_) {
        case 0: prepare_mesh(); break;
        case 1: {
            // With detail, the per-vertex curvature is needed only where a view
            // blends in the raw estimate (zoomed in on a coarse mesh): computed then.
            const bool detail = settings_.detail > 0;
            fields_ = detail && !smoothing_.automatic ? compute_surface_normals(drawn_.mesh, &times_, &adjacency_)
                                                      : compute_fields();
            break;
        }
        case 2: {
            const auto t_scale = std::chrono::steady_clock::now();
            if (settings_.detail > 0) detail_source_ = render::make_detail_source(drawn_.mesh, fields_, &adjacency_);
            else fs_ = feature_size(drawn_.mesh, fields_);  // with detail: per view
            scale_s_ = seconds_since(t_scale);
            break;
        }
        default: return true;
    }
    return ++opened_steps_ == kOpenSteps;
}

void MeshDrawing::prepare_mesh() {
    if (!input_) throw std::logic_error("MeshDrawing: opened again after a failed step");
    Mesh input = std::move(*input_);
    input_.reset();
    // The vertex-face rows serve the preparation (the creases), then (made the split mesh's)
    // the fields and the scale space: built once, timed as the fields' adjacency.
    const auto t_adjacency = std::chrono::steady_clock::now();
    adjacency_ = build_vertex_faces(input);
    times_.adjacency = seconds_since(t_adjacency);
    DrawingPreparation prepared = prepare_for_drawing(input, adjacency_, settings_.crease_angle);
    units_ = prepared.units;
    turned_ = prepared.turned_inside_out;
    outside_out_ = prepared.outside_out;
    crease_angle_ = prepared.creases.angle;
    // Sharp edges split the mesh: each side gets its own normals and curvature.
    drawn_ = split_at_creases(std::move(input), prepared.creases.creases, &adjacency_);
    bounds_ = render::bounding_sphere(drawn_.mesh, prepared.box);  // on every thread, before the clusters take one
    // The first view's triangle order depends on the faces alone: made beside the fields (one
    // thread of work, 2 s for 17.8M faces). A page without threads makes it when it is needed.
    clusters_ = std::async(thread_count() > 1 ? std::launch::async : std::launch::deferred,
                           [this] { return render::MeshBuffers::face_clusters_of(drawn_.mesh, &adjacency_); });
}

render::MeshFacts MeshDrawing::take_mesh_facts() {
    render::MeshFacts facts{&adjacency_, outside_out_, std::nullopt, bounds_};
    if (clusters_.valid()) facts.clusters = clusters_.get();
    return facts;
}

SurfaceFields MeshDrawing::compute_fields() {
    SmoothingOptions o = smoothing_;  // widths in drawing units
    o.normals = units_.length_to_drawing(o.normals), o.curvature = units_.length_to_drawing(o.curvature);
    o.dcurv = units_.length_to_drawing(o.dcurv);
    return compute_surface_fields(drawn_.mesh, o, &times_, progress_, &adjacency_);
}

bool MeshDrawing::view_prepared(const render::Camera& camera, glm::ivec2 size) const {
    return uploaded_ && camera.view == prepared_view_ && camera.fov_y_deg == prepared_fov_ && size == prepared_size_;
}

float MeshDrawing::prepare_view(render::Renderer& renderer, const render::Camera& camera, glm::ivec2 size) {
    work_on_view(renderer, camera, size, std::numeric_limits<double>::infinity(), 0);
    return prepared_fs_;
}

bool MeshDrawing::prepare_view_slice(render::Renderer& renderer, const render::Camera& camera, glm::ivec2 size,
                                     double seconds) {
    constexpr size_t kChunk = 4096;  // vertices or clusters a step: a few ms in WebAssembly
    return work_on_view(renderer, camera, size, seconds, kChunk);
}

bool MeshDrawing::work_on_view(render::Renderer& renderer, const render::Camera& camera, glm::ivec2 size,
                               double seconds, size_t chunk) {
    if (view_prepared(camera, size)) return true;
    const Mesh& mesh = drawn_.mesh;
    if (settings_.detail <= 0) {
        view_fields_ = &fields_;
        if (!uploaded_) {
            renderer.set_mesh(mesh, render::MeshBuffers::prepare(mesh, fields_, fs_, {}, take_mesh_facts()));
            renderer.set_creases(render::crease_end_points(drawn_));
            uploaded_ = true;
        }
        prepared_view_ = camera.view, prepared_fov_ = camera.fov_y_deg, prepared_size_ = size;
        prepared_fs_ = fs_;
        return true;
    }
    const auto start = std::chrono::steady_clock::now();
    const auto time_left = [&] { return seconds - seconds_since(start); };
    PendingView* p = pending_.get();
    if (!p || p->camera.view != camera.view || p->camera.fov_y_deg != camera.fov_y_deg || p->size != size) {
        pending_ = std::make_unique<PendingView>();  // the view moved on: start again
        p = pending_.get();
        p->camera = camera, p->size = size;
        p->scales = render::view_scales(mesh, detail_source_, camera, size.y, settings_.detail);
    }
    if (!p->job) {
        if (!fields_.has_curvature() && render::needs_raw_curvature(detail_source_, p->scales)) {
            fields_ = compute_fields();
            if (time_left() <= 0) return false;
        }
        // From the second view on (an orbit, a turntable), the levels' values at the vertices are kept
        // for the views after it (geometry/scale/level_value_cache.h); a single drawing does without.
        if (uploaded_) detail_source_.space.keep_level_values(true);
        p->job = std::make_unique<render::DetailFieldsJob>(mesh, detail_source_, fields_, p->scales, chunk);
    }
    if (!p->job->done()) {
        if (!p->job->run_for(time_left())) return false;
        p->fields = p->job->take();
        if (time_left() <= 0) return false;
    }
    // The upload's CPU half in steps too; the first view's buffers' layout (the triangles' order) first.
    if (!p->upload) {
        if (!uploaded_ && !p->layout) {
            p->layout = render::MeshBuffers::layout_of(p->fields.mesh, p->fields.fields.flags, take_mesh_facts());
            if (time_left() <= 0) return false;
        }
        p->upload = std::make_unique<render::FieldUploadSteps>(
            p->fields.mesh, p->fields.fields, p->fields.feature_size, p->fields.fine_normals,
            uploaded_ ? renderer.mesh()->face_clusters() : p->layout->clusters, chunk);
    }
    if (!p->upload->done()) {
        if (!p->upload->run_for(time_left()) || time_left() <= 0) return false;
    }
    if (!uploaded_) {
        renderer.set_mesh(p->fields.mesh, {std::move(*p->layout), p->upload->take()});
        renderer.set_creases(render::crease_end_points(drawn_));
        uploaded_ = true;
    } else {
        renderer.upload_fields(p->upload->take());
    }
    view_ = std::move(p->fields);
    view_fields_ = &view_.fields;
    prepared_view_ = camera.view, prepared_fov_ = camera.fov_y_deg, prepared_size_ = size;
    prepared_fs_ = view_.feature_size;
    pending_.reset();
    return true;
}

const Mesh& MeshDrawing::view_surface() {
    // The detail pipeline estimated the noise of the same normals (compute_surface_normals) and
    // denoised the mesh when noisy: no need to do it again.
    if (settings_.detail > 0 && !smoothing_.automatic)
        return detail_source_.denoised_at > 0 ? detail_source_.denoised : drawn_.mesh;
    if (!view_denoised_) view_denoised_ = denoised_if_noisy(drawn_.mesh);
    return *view_denoised_ ? **view_denoised_ : drawn_.mesh;
}

bool MeshDrawing::view_surface_denoised() { return &view_surface() != &drawn_.mesh; }

bool MeshDrawing::same_preparation(const render::RenderSettings& s, const SmoothingOptions& o) const {
    return s.crease_angle == settings_.crease_angle && s.detail == settings_.detail && same_smoothing(o, smoothing_);
}

render::Image MeshDrawing::image(render::Renderer& renderer, const render::Camera& camera,
                                 const render::RenderSettings& settings, glm::ivec2 size) {
    prepare_view(renderer, camera, size);
    return render::render_to_image(renderer, camera, settings, size.x, size.y);
}

render::VectorDrawing MeshDrawing::vectors(render::Renderer& renderer, const render::Camera& camera,
                                           const render::RenderSettings& settings, glm::ivec2 size,
                                           render::Image& underlay) {
    const float fs = prepare_view(renderer, camera, size);
    if (!have_crease_edges_) {
        crease_edges_ = kappa::crease_edges(drawn_.mesh, drawn_.creases, drawn_.crease_faces);
        have_crease_edges_ = true;
    }
    const bool detail = settings_.detail > 0;
    const std::vector<glm::vec3>* fine = detail ? &view_.fine_normals : nullptr;
    const render::StrokeSource source{detail ? &view_.mesh : &drawn_.mesh, view_fields_, fine, &crease_edges_, fs};
    return render::draw_vector_view(renderer, camera, settings, size.x, size.y, source, underlay);
}

void MeshDrawing::write(render::Renderer& renderer, const render::Camera& camera,
                        const render::RenderSettings& settings, glm::ivec2 size, const std::string& path) {
    if (const auto format = render::vector_format_for(path)) {
        render::Image underlay;
        const render::VectorDrawing drawing = vectors(renderer, camera, settings, size, underlay);
        if (*format == render::VectorFormat::Svg) render::write_svg(path, drawing);
        else render::write_pdf(path, drawing);
        return;
    }
    render::write_image(path, image(renderer, camera, settings, size));
}

render::Camera make_camera(const CameraOptions& options, MeshDrawing& drawing, glm::ivec2 size,
                           glm::vec3* orbit_center, glm::vec3* up_axis) {
    const bool default_view = options.uses_default_view();
    const Mesh& surface = default_view ? drawing.view_surface() : drawing.mesh();
    return make_camera(options, surface, drawing.bounds(), size, orbit_center, drawing.units(), up_axis,
                       default_view && drawing.view_surface_denoised(), &drawing.adjacency());
}

}  // namespace kappa::app
