// Loads meshes and estimates curvature on a worker thread, so the viewer's
// window stays responsive (orbiting keeps working) while a large mesh is read
// or a smoothing width is changed. The main thread polls progress() and
// take(); a finished model replaces the old one in a single frame. When a
// new request arrives while one runs, the running one finishes (the
// curvature code cannot be interrupted) and its result is dropped.
#pragma once

#include "app/heap_tuning.h"
#include "geometry/mesh/mesh.h"
#include "geometry/surface_analysis.h"
#include "geometry/surface_fields.h"
#include "render/camera/camera.h"
#include "render/fields/detail_fields.h"
#include "render/fields/mesh_buffers.h"
#include "render/fields/field_upload.h"

#include <atomic>
#include <condition_variable>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace kappa::viewer {

// Numbers shown in the mesh panel.
struct ModelSummary {
    size_t boundary_vertices = 0, flagged_vertices = 0;  // geometry/curvature/vertex_flags.h bits
    float k1_min = 0, k1_max = 0, k2_min = 0, k2_max = 0;  // over reliable vertices
};

// What the load learnt and made of a split mesh that building its GPU buffers would otherwise
// find again (render::MeshFacts): its vertex-face rows (kept for the fields and the scale space
// too), whether its normals point clearly outside after the turn of an inside-out mesh (unknown:
// found when the buffers are built), its face clusters (MeshBuffers::face_clusters_of, one
// thread), made on a thread of their own from the load on, beside the fields, and its bounding
// sphere (from the preparation's box).
struct ModelFacts {
    std::shared_ptr<const VertexFaces> rows;
    std::optional<bool> outside_out;
    std::shared_future<FaceClusters> clusters;
    std::optional<render::BoundingSphere> bounds;
    // For MeshBuffers::prepare: the clusters copied (waited for, when made but not done).
    render::MeshFacts for_buffers() const;
};

// A mesh with everything the renderer needs.
struct Model {
    std::string path;  // empty: the built-in model
    std::shared_ptr<const Mesh> mesh;
    std::shared_ptr<const SurfaceFields> fields;  // the per-vertex estimate (with the smoothing widths)
    float feature_size = 1;                       // of `fields`
    // The scale space for --detail; only the worker touches it after the
    // first view (fitting its levels as zooming needs them).
    std::shared_ptr<render::DetailSource> detail;
    glm::vec3 view_direction{0, 0, 1};  // of the default view (geometry/view/default_view.h)
    glm::vec3 view_up{0, 1, 0};         // the up axis it stands on
    std::vector<glm::vec3> crease_points;  // the crease pass's data (render/fields/field_upload.h); `mesh` is split there
    size_t input_vertices = 0;             // before the split
    ModelFacts facts;  // the viewer drops the clusters once the first view is shown
    SmoothingOptions smoothing;
    ModelSummary summary;
    StageTimes stages;
    double load_s = 0, fields_s = 0;  // wall-clock seconds: reading the file, curvature + feature size
};

ModelSummary summarize(const SurfaceFields& fields);

class BackgroundCompute {
public:
    BackgroundCompute();
    ~BackgroundCompute();  // waits for the running job
    BackgroundCompute(const BackgroundCompute&) = delete;
    BackgroundCompute& operator=(const BackgroundCompute&) = delete;

    // Reads `path` ("" = the built-in model), then computes its fields. With
    // normals_first (drawings at a detail scale need only the normals to
    // start), the model arrives with normals, areas and flags, and the full
    // per-vertex fields follow as a completion (take_completion).
    // crease_angle: RenderSettings::crease_angle (the mesh is split at its
    // sharp edges, geometry/mesh/creases.h).
    void load(const std::string& path, const SmoothingOptions& smoothing, bool normals_first = false,
              float crease_angle = -1.0f);
    // Recomputes the fields of an already loaded mesh with new widths.
    void recompute(const Model& model, const SmoothingOptions& smoothing);

    // Fields at the detail scale of a new view, prepared for upload
    // (render/fields/field_upload.h), for the model already shown. A newer request
    // replaces an older one not yet started. Without clusters, a model's first
    // view: its fields come back whole (ViewResult::first), for Renderer::set_mesh.
    struct ViewRequest {
        std::shared_ptr<const Mesh> mesh;
        std::shared_ptr<const SurfaceFields> fields;
        std::shared_ptr<render::DetailSource> detail;
        std::shared_ptr<const FaceClusters> clusters;  // of the fields shown; null: a first view
        render::Camera camera;
        int height = 1;
        float detail_px = 0;
        ModelFacts facts;  // the model's, for a first view's buffers
        // A first view for a software GL: the window thread's block for its buffers
        // (MeshBuffers::landing_bytes), faulted in here once they are prepared (app/heap_tuning.h).
        std::shared_ptr<app::HeapBlock> buffer_memory;
    };
    struct ViewResult {
        std::shared_ptr<const Mesh> mesh;  // whose fields these are
        render::FieldUpload upload;
        // A first view instead: its fields and all that building their buffers computes before
        // any GL call (MeshBuffers::prepare), so that the window's thread only sends them.
        struct First {
            render::DetailFields fields;
            render::MeshBuffers::Prepared buffers;
        };
        std::shared_ptr<First> first;
        render::Camera camera;
        int height = 1;
        float detail_px = 0;
    };
    void request_view(ViewRequest request);
    std::optional<ViewResult> take_view();
    bool view_busy() const { return view_busy_; }

    bool busy() const { return busy_; }
    float progress() const { return progress_; }  // of the running job, in [0, 1]
    std::string stage() const;                    // "loading", "normals", ...

    // The newest request's result once it is ready (then nullopt until the
    // next). An error message instead when the mesh could not be read.
    struct Result {
        std::optional<Model> model;
        std::string error;
    };
    std::optional<Result> take();

    // The full fields of a model that arrived with normals only.
    struct Completion {
        std::shared_ptr<const Mesh> mesh;  // whose fields these are
        std::shared_ptr<const SurfaceFields> fields;
        float feature_size = 1;
        ModelSummary summary;
        StageTimes stages;
        double fields_s = 0;
    };
    std::optional<Completion> take_completion();
    // Computes a completion; the viewer's thread calls it too, when a view
    // needs the full fields before the worker has them.
    static Completion complete(std::shared_ptr<const Mesh> mesh, const SmoothingOptions& smoothing);
    // Called after each drawn frame: a completion starts only after the
    // frame that shows its model, so it does not slow that frame down.
    void frame_drawn();
    // Called when a first view (ViewResult::first) is on the GPU, or will not be: the
    // completion waits for it.
    void first_view_shown();

private:
    struct Request {
        std::string path;
        std::shared_ptr<const Mesh> mesh;  // set: recompute only
        SmoothingOptions smoothing;
        bool normals_first = false;
        float crease_angle = -1.0f;
        std::vector<glm::vec3> crease_points;  // recompute: the model's, kept
        size_t input_vertices = 0;
        ModelFacts facts;  // recompute: the model's, kept
        unsigned generation = 0;
    };
    void submit(Request request);
    void run();
    Result execute(const Request& request);
    ViewResult execute_view(const ViewRequest& request);
    // Runs a pending view request, if any (the lock held on entry and on return).
    void run_pending_view(std::unique_lock<std::mutex>& lock);

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Request> pending_;
    std::optional<Result> done_;
    unsigned generation_ = 0;  // of the newest request
    bool quit_ = false;
    std::atomic<bool> busy_{false};
    std::optional<Completion> done_completion_;
    bool frame_since_result_ = true;  // guarded by mutex_
    bool first_view_out_ = false;     // a first view is with the window, not yet shown; guarded by mutex_
    std::optional<ViewRequest> pending_view_;
    std::optional<ViewResult> done_view_;
    std::atomic<bool> view_busy_{false};
    std::atomic<float> progress_{0};
    std::string stage_;  // guarded by mutex_
    std::thread worker_;  // last: starts once every member above exists
};

}  // namespace kappa::viewer
