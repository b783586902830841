// One mesh prepared for drawing, and its views: what `kappa render`, each
// mesh of `kappa batch` and the Python module's render() and strokes() share.
// The mesh is split at its sharp edges (geometry/mesh/creases.h), its fields are
// computed once (with --detail: the scale space, and per view the fields at
// the view's scale, render/fields/detail_fields.h), uploaded on the first view and
// updated per view when they follow the view.
#pragma once

#include "render_options.h"

#include "geometry/mesh/creases.h"
#include "geometry/mesh/drawing_units.h"
#include "geometry/surface_analysis.h"
#include "render/camera/camera.h"
#include "render/fields/detail_fields.h"
#include "render/fields/detail_fields_job.h"
#include "render/fields/field_upload.h"
#include "render/image/image.h"
#include "render/render_settings.h"
#include "render/renderer.h"
#include "render/vector/vector_drawing.h"

#include <glm/vec2.hpp>

#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace kappa::app {

class MeshDrawing {
public:
    // `settings` decides the crease angle and the detail (the fields of each
    // view); progress reports the curvature computation. Views may be drawn
    // with other appearance settings (lines, shading, ...), not other crease
    // angle or detail: same_preparation tells.
    MeshDrawing(Mesh input, const render::RenderSettings& settings, const SmoothingOptions& smoothing,
                const ProgressFn& progress = {});
    MeshDrawing(const MeshDrawing&) = delete;  // a thread of its own reads mesh() and adjacency() (clusters_)
    MeshDrawing& operator=(const MeshDrawing&) = delete;
    // The same work in steps, for a page that has one thread (web/): the constructor keeps the
    // mesh, then each open_step does one of the first constructor's stages (the preparation and
    // split, the fields, the scale space) and returns true once the drawing is open. Nothing
    // else may be asked of the drawing before.
    struct InSteps {};
    MeshDrawing(Mesh input, const render::RenderSettings& settings, const SmoothingOptions& smoothing, InSteps);
    bool open_step();
    bool opened() const { return opened_steps_ == kOpenSteps; }

    // The mesh as drawn, and its bounds: in drawing units (geometry/mesh/drawing_units.h), which are the
    // model's own but for meshes far from unit size; cameras are in the same units (make_camera).
    const Mesh& mesh() const { return drawn_.mesh; }
    const render::BoundingSphere& bounds() const { return bounds_; }
    const DrawingUnits& units() const { return units_; }
    // mesh()'s vertex-face rows; view_surface() has the same faces.
    const VertexFaces& adjacency() const { return adjacency_; }
    // Whether the input was inside out (geometry/mesh/orientation.h) and is drawn with its faces turned.
    bool turned_inside_out() const { return turned_; }
    size_t crease_count() const { return drawn_.creases.size(); }
    float crease_angle() const { return crease_angle_; }
    const StageTimes& times() const { return times_; }
    double scale_seconds() const { return scale_s_; }  // feature size, or the scale space with detail
    float noise_floor() const { return units_.length_to_model(detail_source_.noise_floor); }  // model units
    // The surface the default view reads (make_camera): mesh(), denoised at its noise floor when it
    // is noisy (geometry/scale/denoise.h). With detail, the detail pipeline's own denoised mesh and
    // noise estimate; without, estimated on first use.
    const Mesh& view_surface();
    // Whether view_surface() is the mesh denoised (its flat faces smaller than the denoising
    // scale are gone: geometry/view/default_view.h's choose_up).
    bool view_surface_denoised();

    // Uploads the fields of this view to `renderer` (the whole mesh on the
    // first view; nothing when this view was the last one prepared). The
    // renderer must draw no other mesh between views. Returns the view's
    // feature size.
    float prepare_view(render::Renderer& renderer, const render::Camera& camera, glm::ivec2 size);
    // The same spread over calls, for a page that has one thread (web/): works on this view's
    // fields for about `seconds` (at least one step of render/fields/detail_fields_job.h, cut
    // into pieces of a few thousand vertices) and returns true once they are uploaded. A call for
    // another view drops the work in progress and starts on that one (the scale space's levels
    // fitted so far are kept). Until then the renderer keeps the fields it has.
    bool prepare_view_slice(render::Renderer& renderer, const render::Camera& camera, glm::ivec2 size,
                            double seconds);
    // Whether this view's fields are the ones uploaded.
    bool view_prepared(const render::Camera& camera, glm::ivec2 size) const;

    // The view as an RGBA image (prepare_view, then render_to_image).
    render::Image image(render::Renderer& renderer, const render::Camera& camera,
                        const render::RenderSettings& settings, glm::ivec2 size);
    // The view as strokes (render/vector/vector_view.h); the surface picture goes
    // to underlay (the drawing points at it).
    render::VectorDrawing vectors(render::Renderer& renderer, const render::Camera& camera,
                                  const render::RenderSettings& settings, glm::ivec2 size, render::Image& underlay);
    // Writes the view to `path`: .png/.jpg/.jpeg, .svg or .pdf.
    // Throws std::runtime_error "PATH: reason".
    void write(render::Renderer& renderer, const render::Camera& camera, const render::RenderSettings& settings,
               glm::ivec2 size, const std::string& path);

    // Whether a drawing made with these options would be prepared the same
    // (crease angle, detail, curvature options), so this one can serve it.
    bool same_preparation(const render::RenderSettings& settings, const SmoothingOptions& smoothing) const;

private:
    SurfaceFields compute_fields();
    void prepare_mesh();  // the first step: units, creases, orientation, the split, the clusters' start
    // What the preparation found or made that building the GPU buffers would find again: the
    // rows, the orientation and the face clusters (a view's detail fields move the positions
    // alone, so they serve its mesh too). Once: the clusters are moved out.
    render::MeshFacts take_mesh_facts();
    // prepare_view's work for at most about `seconds`; chunk: DetailFieldsJob's.
    bool work_on_view(render::Renderer& renderer, const render::Camera& camera, glm::ivec2 size, double seconds,
                      size_t chunk);

    render::RenderSettings settings_;
    SmoothingOptions smoothing_;  // as given (model units)
    std::optional<Mesh> input_;   // until the first step
    static constexpr int kOpenSteps = 3;
    int opened_steps_ = 0;
    DrawingUnits units_;
    bool turned_ = false;
    bool outside_out_ = false;  // DrawingPreparation's
    ProgressFn progress_;
    float crease_angle_ = 0;
    SplitMesh drawn_;
    VertexFaces adjacency_;  // drawn_.mesh's vertex-face rows
    // drawn_.mesh's face clusters (MeshBuffers::face_clusters_of, serial), made on a thread of
    // their own while the fields are computed, for the first view's buffers.
    std::future<FaceClusters> clusters_;
    render::BoundingSphere bounds_;
    StageTimes times_;
    SurfaceFields fields_;
    render::DetailSource detail_source_;
    std::optional<std::optional<Mesh>> view_denoised_;  // without detail: denoised_if_noisy, once asked
    float fs_ = 0;  // without detail
    double scale_s_ = 0;
    std::vector<CreaseEdge> crease_edges_;  // for strokes, made on first use
    bool have_crease_edges_ = false;
    render::DetailFields view_;             // with detail: the last view's fields
    const SurfaceFields* view_fields_ = nullptr;
    bool uploaded_ = false;
    // The view last prepared (with detail, the fields depend on it).
    glm::mat4 prepared_view_{0};
    float prepared_fov_ = 0, prepared_fs_ = 0;
    glm::ivec2 prepared_size_{0};
    // With detail, a view's fields on their way (prepare_view_slice).
    struct PendingView {
        render::Camera camera;
        glm::ivec2 size{0};
        render::ViewScales scales;
        std::unique_ptr<render::DetailFieldsJob> job;  // made once the raw fields it needs are there
        render::DetailFields fields;                   // the job's, once done
        // The first view's buffers' layout: the triangles' order (face clusters), the back faces
        // (one step: a slice that ran out of time after it must not make it again).
        std::optional<render::MeshBuffers::MeshLayout> layout;
        std::unique_ptr<render::FieldUploadSteps> upload;  // their CPU half
    };
    std::unique_ptr<PendingView> pending_;
};

// make_camera (render_options.h) for a drawing: its bounds and units, and its view_surface, asked
// for only when the camera is the default view.
render::Camera make_camera(const CameraOptions& options, MeshDrawing& drawing, glm::ivec2 size,
                           glm::vec3* orbit_center = nullptr, glm::vec3* up_axis = nullptr);

}  // namespace kappa::app
