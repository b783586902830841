#include "app/viewer/background_compute.h"

#include "app/heap_tuning.h"
#include "app/mesh_source.h"
#include "geometry/mesh/creases.h"
#include "geometry/curvature/feature_size.h"
#include "geometry/view/default_view.h"
#include "render/fields/mesh_buffers.h"
#include "render/render_settings.h"
#include "geometry/io/mesh_io.h"
#include "geometry/curvature/vertex_flags.h"

#include <algorithm>
#include <chrono>
#include <future>
#include <limits>

namespace kappa::viewer {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ModelSummary summarize(const SurfaceFields& f) {
    ModelSummary s;
    float inf = std::numeric_limits<float>::infinity();
    s.k1_min = s.k2_min = inf;
    s.k1_max = s.k2_max = -inf;
    for (size_t i = 0; i < f.size(); ++i) {
        const uint8_t flags = i < f.flags.size() ? f.flags[i] : 0;
        if (flags & kFlagBoundary) ++s.boundary_vertices;
        if (flags & kFlagUnreliable) {
            ++s.flagged_vertices;
            continue;
        }
        s.k1_min = std::min(s.k1_min, f.k1[i]), s.k1_max = std::max(s.k1_max, f.k1[i]);
        s.k2_min = std::min(s.k2_min, f.k2[i]), s.k2_max = std::max(s.k2_max, f.k2[i]);
    }
    if (s.k1_min > s.k1_max) s.k1_min = s.k1_max = s.k2_min = s.k2_max = 0;  // no reliable vertex
    return s;
}

BackgroundCompute::BackgroundCompute() : worker_([this] { run(); }) {}

BackgroundCompute::~BackgroundCompute() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        quit_ = true;
        pending_.reset();
    }
    wake_.notify_one();
    worker_.join();
}

void BackgroundCompute::load(const std::string& path, const SmoothingOptions& smoothing, bool normals_first,
                             float crease_angle) {
    Request r;
    r.path = path;
    r.smoothing = smoothing;
    r.crease_angle = crease_angle;
    r.normals_first = normals_first && !smoothing.automatic && !(smoothing.normals > 0) &&
                      !(smoothing.curvature > 0) && !(smoothing.dcurv > 0);
    submit(std::move(r));
}

void BackgroundCompute::frame_drawn() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (frame_since_result_ || done_) return;  // nothing waits, or the result is not shown yet
        frame_since_result_ = true;
    }
    wake_.notify_one();
}

render::MeshFacts ModelFacts::for_buffers() const {
    render::MeshFacts facts{rows.get(), outside_out, std::nullopt, bounds};
    if (clusters.valid()) facts.clusters = clusters.get();
    return facts;
}

void BackgroundCompute::first_view_shown() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        first_view_out_ = false;
    }
    wake_.notify_one();
}

std::optional<BackgroundCompute::Completion> BackgroundCompute::take_completion() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::optional<Completion> r = std::move(done_completion_);
    done_completion_.reset();
    return r;
}

BackgroundCompute::Completion BackgroundCompute::complete(std::shared_ptr<const Mesh> mesh,
                                                          const SmoothingOptions& smoothing) {
    Completion c;
    const auto t = std::chrono::steady_clock::now();
    auto fields = std::make_shared<SurfaceFields>(compute_surface_fields(*mesh, smoothing, &c.stages));
    c.feature_size = feature_size(*mesh, *fields);
    c.summary = summarize(*fields);
    c.fields_s = seconds_since(t);
    c.fields = std::move(fields);
    c.mesh = std::move(mesh);
    return c;
}

void BackgroundCompute::recompute(const Model& model, const SmoothingOptions& smoothing) {
    Request r;
    r.path = model.path;
    r.mesh = model.mesh;
    r.smoothing = smoothing;
    r.crease_points = model.crease_points;
    r.input_vertices = model.input_vertices;
    r.facts = model.facts;
    submit(std::move(r));
}

void BackgroundCompute::submit(Request request) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        request.generation = ++generation_;
        pending_ = std::move(request);
        done_.reset();  // an older result is out of date now
        busy_ = true;
    }
    wake_.notify_one();
}

std::string BackgroundCompute::stage() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return stage_;
}

std::optional<BackgroundCompute::Result> BackgroundCompute::take() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::optional<Result> r = std::move(done_);
    done_.reset();
    return r;
}

void BackgroundCompute::request_view(ViewRequest request) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        pending_view_ = std::move(request);
        view_busy_ = true;
    }
    wake_.notify_one();
}

std::optional<BackgroundCompute::ViewResult> BackgroundCompute::take_view() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::optional<ViewResult> r = std::move(done_view_);
    done_view_.reset();
    return r;
}

BackgroundCompute::ViewResult BackgroundCompute::execute_view(const ViewRequest& r) {
    ViewResult out;
    out.mesh = r.mesh;
    out.camera = r.camera;
    out.height = r.height;
    out.detail_px = r.detail_px;
    const render::ViewScales scales = render::view_scales(*r.mesh, *r.detail, r.camera, r.height, r.detail_px);
    std::shared_ptr<const SurfaceFields> fields = r.fields;
    if (!fields->has_curvature() && render::needs_raw_curvature(*r.detail, scales)) {
        Completion c = complete(r.mesh, {});  // zoomed in on a coarse mesh before its fields were complete
        fields = c.fields;
        std::lock_guard<std::mutex> lock(mutex_);
        done_completion_ = std::move(c);
    }
    render::DetailFields d = render::detail_fields(*r.mesh, *r.detail, *fields, scales);
    if (!r.clusters) {  // a first view: the buffers' layout made here too
        auto first = std::make_shared<ViewResult::First>();
        first->buffers =
            render::MeshBuffers::prepare(d.mesh, d.fields, d.feature_size, d.fine_normals, r.facts.for_buffers());
        if (r.buffer_memory) r.buffer_memory->fault_in();
        first->fields = std::move(d);
        out.first = std::move(first);
        return out;
    }
    out.upload = render::prepare_field_upload(d.mesh, d.fields, d.feature_size, d.fine_normals, *r.clusters);
    return out;
}

void BackgroundCompute::run_pending_view(std::unique_lock<std::mutex>& lock) {
    if (!pending_view_) return;
    ViewRequest view = std::move(*pending_view_);
    pending_view_.reset();
    lock.unlock();
    ViewResult result = execute_view(view);
    lock.lock();
    done_view_ = std::move(result);
    view_busy_ = bool(pending_view_);
}

void BackgroundCompute::run() {
    for (;;) {
        Request request;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return quit_ || pending_ || pending_view_; });
            if (quit_) return;
            if (!pending_) {  // a view's fields; models first
                run_pending_view(lock);
                continue;
            }
            request = std::move(*pending_);
            pending_.reset();
            progress_ = 0;
        }
        Result result = execute(request);
        std::shared_ptr<const Mesh> to_complete;
        if (result.model && !result.model->fields->has_curvature()) to_complete = result.model->mesh;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            if (request.generation == generation_) {  // still the newest request
                done_ = std::move(result);
                busy_ = false;
            }
            if (to_complete) {  // after the frame that shows the model
                frame_since_result_ = false;
                wake_.wait(lock, [this] { return quit_ || pending_ || frame_since_result_; });
                // A big model's first view (asked for as the model arrived) goes before the completion,
                // and the completion waits until the window has sent it to the GPU: beside the
                // completion's threads, faulting in memory of their own, llvmpipe took 6.4 s instead
                // of 4.5 s to make the buffers for a 17.8M-face mesh (docs/gpu.md).
                if (!quit_ && !pending_) {
                    run_pending_view(lock);
                    first_view_out_ = done_view_ && done_view_->first;
                    wake_.wait(lock, [this] { return quit_ || pending_ || pending_view_ || !first_view_out_; });
                }
            }
            if (quit_) return;
            if (pending_) continue;  // a newer model is wanted: never mind completing this one
        }
        if (to_complete) {
            Completion c = complete(to_complete, request.smoothing);
            std::lock_guard<std::mutex> lock(mutex_);
            done_completion_ = std::move(c);
        }
    }
}

BackgroundCompute::Result BackgroundCompute::execute(const Request& request) {
    Result result;
    Model m;
    m.path = request.path;
    m.smoothing = request.smoothing;
    const auto set_stage = [this](const char* stage) {
        std::lock_guard<std::mutex> lock(mutex_);
        stage_ = stage;
    };
    try {
        if (request.mesh) {
            m.mesh = request.mesh;
            m.crease_points = request.crease_points;
            m.input_vertices = request.input_vertices;
            m.facts = request.facts;
        } else {
            set_stage("loading");
            const auto t = std::chrono::steady_clock::now();
            Mesh input = app::load_mesh_or_default(request.path);
            auto rows = std::make_shared<VertexFaces>(build_vertex_faces(input));
            // The angle (auto or given) and the creases, as kappa render (app/mesh_drawing.cpp).
            const app::DrawingPreparation prepared = app::prepare_for_drawing(input, *rows, request.crease_angle);
            m.input_vertices = input.vertex_count();
            SplitMesh split = split_at_creases(std::move(input), prepared.creases.creases, rows.get());
            m.facts.rows = std::move(rows);
            m.facts.outside_out = prepared.outside_out;
            m.facts.bounds = render::bounding_sphere(split.mesh, prepared.box);
            m.crease_points = render::crease_end_points(split);
            m.mesh = std::make_shared<const Mesh>(std::move(split.mesh));
            m.load_s = seconds_since(t);
        }
        // The first view's triangle order depends on the faces alone: made beside the fields (one
        // thread of work, 2 s for 17.8M faces), as kappa render's MeshDrawing does.
        if (m.facts.rows && !m.facts.clusters.valid())
            m.facts.clusters = std::async(std::launch::async, [mesh = m.mesh, rows = m.facts.rows] {
                return render::MeshBuffers::face_clusters_of(*mesh, rows.get());
            }).share();
        const auto t = std::chrono::steady_clock::now();
        const auto report = [&](float f, const char* stage) {
            progress_ = f;
            set_stage(stage);
        };
        const VertexFaces* rows = m.facts.rows.get();
        auto fields = std::make_shared<SurfaceFields>(
            request.normals_first ? compute_surface_normals(*m.mesh, &m.stages, rows)
                                  : compute_surface_fields(*m.mesh, request.smoothing, &m.stages, report, rows));
        set_stage("feature size");
        if (fields->has_curvature()) m.feature_size = feature_size(*m.mesh, *fields);
        set_stage("scale space");
        m.detail = std::make_shared<render::DetailSource>(render::make_detail_source(*m.mesh, *fields, rows));
        set_stage("default view");
        // As kappa render's (app/mesh_drawing.cpp, view_surface): from the raw normals the scale space
        // estimated the noise and denoised a noisy mesh already; other fields are smoothed, so the
        // view reads the mesh at its own noise floor.
        const std::optional<glm::vec3> up = file_up_axis(request.path);
        const bool denoised = m.detail->denoised_at > 0;
        const DefaultView view = request.normals_first
                                     ? default_view_as_read(denoised ? m.detail->denoised : *m.mesh, up, denoised, rows)
                                     : default_view(*m.mesh, up);
        m.view_direction = view.eye, m.view_up = view.up;
        m.fields_s = seconds_since(t);
        if (fields->has_curvature()) m.summary = summarize(*fields);
        m.fields = std::move(fields);
        result.model = std::move(m);
    } catch (const std::bad_alloc&) {
        result.error = (request.path.empty() ? "built-in model" : request.path) + ": out of memory";
    } catch (const std::exception& e) {  // kappa::MeshLoadError: "PATH: problem"
        result.error = e.what();
    }
    progress_ = 1;
    return result;
}

}  // namespace kappa::viewer
