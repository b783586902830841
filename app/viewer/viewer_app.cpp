#include "app/viewer/viewer_app.h"

#include "render/gl/gl.h"
#include "render/gl/gl_loader.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cstdio>

namespace kappa::viewer {

namespace {

// Meshes from this size on get a first frame without MSAA (about half the time in software).
constexpr size_t kQuickFirstFrameFaces = 500000;
// Meshes from this size on get their first view's detail fields from the worker, as later views
// do: made on this thread they froze the window (about 1 s for bunny-1M, 20 s for 17.8M faces on
// 2 cores).
constexpr size_t kFirstViewOnWorkerFaces = 1000000;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <typename Container>
float median(Container v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// A model that arrived with normals only takes its full per-vertex fields.
void adopt_fields(Model& model, BackgroundCompute::Completion c) {
    model.fields = std::move(c.fields);
    model.feature_size = c.feature_size;
    model.summary = c.summary;
    model.stages = c.stages;
    model.fields_s += c.fields_s;
}

}  // namespace

ViewerApp::ViewerApp(ViewerOptions options) : options_(std::move(options)), state_(options_.state) {
    panel_.visible = options_.show_panel;
    if (!options_.xf_path.empty()) panel_.view_path = options_.xf_path;
    // Reading the mesh and estimating curvature overlap with opening the
    // window and compiling the shaders.
    compute_.load(options_.mesh_path, state_.smoothing, effective_detail() > 0, state_.settings.crease_angle);
}

ViewerApp::~ViewerApp() {
    if (window_) {  // GL objects go while the context is there
        landing_.reset();
        renderer_.reset();
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
}

ViewerApp::Area ViewerApp::drawing_area() const {
    const glm::vec2 window(window_->window_size());
    const float panel = panel_.visible ? std::min(panel_width(window_->content_scale()), 0.5f * window.x) : 0.0f;
    Area a;
    a.origin = {panel, 0};
    a.size = glm::max(glm::vec2(window.x - panel, window.y), glm::vec2(1));
    a.pixels = glm::max(glm::ivec2(glm::round(a.size * window_->pixel_ratio())), glm::ivec2(1));
    return a;
}

render::Camera ViewerApp::camera() const { return orbit_.camera(glm::vec2(drawing_area().pixels)); }

void ViewerApp::open_window() {
    render::WindowContext::Options wo;
    wo.width = options_.size.x;
    wo.height = options_.size.y;
    wo.title = "kappa - " + (options_.mesh_path.empty() ? std::string("built-in model") : options_.mesh_path);
    wo.vsync = !options_.scripted();  // scripted runs go as fast as they can
    window_ = render::WindowContext::create(wo);
    renderer_ = std::make_unique<render::Renderer>();
    renderer_->set_complete_frames(false);  // a frame never waits for the compute path's segment count
    // Streamline hatching traced in the background once the view rests, the shader's strokes until then;
    // the worker wakes the event loop when they are ready.
    renderer_->set_interactive_hatching(true);
    renderer_->set_hatching_done([] { glfwPostEmptyEvent(); });

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's directory
    ImGui::StyleColorsDark();
    const float scale = window_->content_scale();  // high-DPI screens
    ImGui::GetStyle().ScaleAllSizes(scale);
    ImGui::GetIO().FontGlobalScale = scale;
    install_callbacks();  // before ImGui's, which chain to ours
    ImGui_ImplGlfw_InitForOpenGL(window_->handle(), true);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    if (!options_.xf_path.empty()) load_view(options_.xf_path);
}

int ViewerApp::run() {
    open_window();
    while (!window_->should_close()) {
        wait_for_events();
        adopt_results();
        request_view_fields();
        if (options_.scripted() && !script_step()) break;
        draw_frame();
    }
    if (options_.scripted() && exit_status_ == 0)  // a failed run says only what failed
        std::printf("frames: %zu still, median %.1f ms; %zu while dragging, median %.1f ms; "
                    "new fields landed %zu times, longest %.1f ms\n",
                    still_ms_.size(), median(still_ms_), moving_ms_.size(), median(moving_ms_), landing_ms_.size(),
                    landing_ms_.empty() ? 0.0f : *std::max_element(landing_ms_.begin(), landing_ms_.end()));
    return exit_status_;
}

void ViewerApp::wait_for_events() {
    if (drag_button_ >= 0) {
        glfwPollEvents();  // orbiting: as many frames as the machine draws
    } else if (renderer_->field_upload_pending() || landing_) {
        glfwPollEvents();  // new fields on their way to the GPU, a slice a frame
    } else if (compute_.busy() || first_view_pending_ || renderer_->hatching_pending()) {
        glfwWaitEventsTimeout(0.05);  // the progress bar moves; the computation gets the cores
    } else if (options_.scripted() || redraw_frames_ > 0) {
        glfwPollEvents();
    } else {
        glfwWaitEvents();  // idle: nothing changes until an event
        redraw_frames_ = 2;
    }
    redraw_frames_ = std::max(redraw_frames_ - 1, 0);
}

// A finished load or recompute replaces the current model within this frame.
void ViewerApp::adopt_results() {
    // The full per-vertex fields of a model that arrived with normals only:
    // the drawing does not change (it is at the detail scale), the panel's
    // numbers and `--detail off` get them.
    if (auto c = compute_.take_completion(); c && model_ && c->mesh == model_->mesh) {
        adopt_fields(*model_, std::move(*c));
        redraw_frames_ = 2;
    }
    auto result = compute_.take();
    if (!result) return;
    redraw_frames_ = 2;
    if (!result->model) {
        report(result->error, true);
        if (!model_ && options_.scripted()) exit_status_ = 1;  // the requested mesh never opened
        return;
    }
    const bool new_mesh = !model_ || model_->mesh != result->model->mesh;
    if (!new_mesh) result->model->load_s = model_->load_s;  // a recompute read no file
    model_ = std::move(result->model);
    // A big new mesh shows up at once without multisampling; the frame after is full quality.
    quick_frame_ = model_->mesh->face_count() >= kQuickFirstFrameFaces;
    if (new_mesh) {
        const render::BoundingSphere bounds =
            model_->facts.bounds ? *model_->facts.bounds : render::bounding_sphere(*model_->mesh);
        if (have_view_)
            orbit_.set_pivot(bounds.center);
        else
            orbit_.reset(bounds, drawing_area().size, model_->view_direction, model_->view_up);
        have_view_ = false;  // a view file applies to the first mesh only
        window_->set_title("kappa - " + (model_->path.empty() ? std::string("built-in model") : model_->path));
        panel_.open_path = model_->path;
    }
    // The first view's detail fields are made here, so the first frame is
    // already right; later views get theirs from the worker. A big mesh's
    // too: the frames until they come show the progress (and the drawing
    // before, if any).
    first_view_pending_ = false;
    landing_.reset();
    buffer_memory_.reset();  // a first view asked for before, if any, is not landing
    if (effective_detail() > 0 && model_->mesh->face_count() >= kFirstViewOnWorkerFaces) request_first_view();
    else show_model();
}

// The model's fields for the current view, made on this thread.
void ViewerApp::show_model() {
    const auto t = std::chrono::steady_clock::now();
    shown_ = {effective_detail(), camera(), drawing_area().pixels.y};
    const auto complete_fields = [&] {  // on this thread: only small meshes or rare views need it
        if (!model_->fields->has_curvature())
            adopt_fields(*model_, BackgroundCompute::complete(model_->mesh, state_.smoothing));
    };
    if (shown_.detail > 0) {
        const render::ViewScales scales =
            render::view_scales(*model_->mesh, *model_->detail, shown_.camera, shown_.height, shown_.detail);
        if (render::needs_raw_curvature(*model_->detail, scales)) complete_fields();
        const render::DetailFields d = render::detail_fields(*model_->mesh, *model_->detail, *model_->fields, scales);
        renderer_->set_mesh(d.mesh, render::MeshBuffers::prepare(d.mesh, d.fields, d.feature_size, d.fine_normals,
                                                                  model_->facts.for_buffers()));
    } else {
        complete_fields();
        renderer_->set_mesh(*model_->mesh,
                            render::MeshBuffers::prepare(*model_->mesh, *model_->fields, model_->feature_size, {},
                                                         model_->facts.for_buffers()));
    }
    mesh_uploaded(float(seconds_since(t)));
}

// After Renderer::set_mesh: the model's creases, the clusters later views are prepared in, the
// window thread's time the upload took.
void ViewerApp::mesh_uploaded(float window_s) {
    renderer_->set_creases(model_->crease_points);
    face_clusters_ = renderer_->mesh()->shared_face_clusters();
    model_->facts.clusters = {};  // the uploaded ones serve from now on
    upload_s_ = window_s;
}

void ViewerApp::request_first_view() {
    first_view_pending_ = true;
    shown_ = {effective_detail(), camera(), drawing_area().pixels.y};
    // A software GL makes the buffers in this thread's heap: their pages are faulted in on the worker.
    buffer_memory_.reset();
    if (renderer_->software_gl())
        buffer_memory_ = std::make_shared<app::HeapBlock>(render::MeshBuffers::landing_bytes(*model_->mesh));
    compute_.request_view({model_->mesh, model_->fields, model_->detail, nullptr, shown_.camera, shown_.height,
                           shown_.detail, model_->facts, buffer_memory_});
}

// A big model's first view from the worker, its upload prepared there: sent in slices over the
// next frames, as later views' fields are (17.8M faces: 1.1 GB, 7.6 s of GL calls on llvmpipe
// sent whole), while the frames go on showing the progress (and the drawing before, if any).
void ViewerApp::show_first_view(BackgroundCompute::ViewResult::First& first, const render::Camera& camera,
                                int height) {
    const auto t = std::chrono::steady_clock::now();
    buffer_memory_.reset();  // freed for the buffers made now
    landing_ = std::make_unique<render::MeshBuffers>(first.fields.mesh, std::move(first.buffers),
                                                     render::MeshBuffers::InSlices{});
    landing_view_ = {shown_.detail, camera, height};
    upload_s_ = 0;
    landing_slices_ = landing_frames_ = 0;
    landing_longest_ms_ = 0;
    continue_first_landing(t);  // this frame's share: the empty buffers made, then slices
}

// A frame's share of the first view's slices (send_slices); the frame after the last one draws it.
void ViewerApp::continue_first_landing(std::chrono::steady_clock::time_point since) {
    const bool done = send_slices(since, [&](size_t bytes) {
        ++landing_slices_;
        return landing_->upload_step(bytes);
    });
    const float share = float(seconds_since(since));
    landing_longest_ms_ = std::max(landing_longest_ms_, 1e3f * share);
    upload_s_ += share;
    redraw_frames_ = 2;
    if (!done) return;
    const auto t = std::chrono::steady_clock::now();
    renderer_->set_mesh(std::move(landing_));
    mesh_uploaded(upload_s_ + float(seconds_since(t)));
    shown_ = landing_view_;
    first_view_pending_ = false;
    compute_.first_view_shown();
    quick_frame_ = model_->mesh->face_count() >= kQuickFirstFrameFaces;
}

float ViewerApp::effective_detail() const {
    const SmoothingOptions& w = state_.smoothing;
    // As in `kappa render`: explicit widths, or another estimator than the default, draw the raw fields.
    const bool raw = w.normals > 0 || w.curvature > 0 || w.dcurv > 0 || w.estimator != Estimator::rusinkiewicz;
    return raw ? 0.0f : state_.settings.detail;
}

// The fields follow the view's scale: after a zoom (pixel size at the pivot
// changed by more than 10%), a turn of more than 10 degrees, a new window
// height or detail setting, the worker prepares new ones (never while
// dragging: the frame after the release asks).
void ViewerApp::request_view_fields() {
    if (first_view_pending_ && landing_) {
        continue_first_landing(std::chrono::steady_clock::now());
        if (first_view_pending_) return;
    } else if (first_view_pending_) {
        if (auto done = compute_.take_view(); done && done->first) {
            if (done->mesh == model_->mesh && done->detail_px == effective_detail())
                show_first_view(*done->first, done->camera, done->height);
            else if (effective_detail() > 0)
                request_first_view();  // the settings changed meanwhile: again with the new ones
            else {  // detail off: the model's own fields
                first_view_pending_ = false;
                compute_.first_view_shown();
                show_model();
            }
        }
        if (first_view_pending_) return;
    }
    if (!model_ || !renderer_->mesh()) return;
    if (auto done = compute_.take_view()) {
        if (!done->first && done->mesh == model_->mesh && done->detail_px == effective_detail()) {
            const auto t = std::chrono::steady_clock::now();
            renderer_->begin_field_upload(std::move(done->upload));
            continue_field_upload(t);
            shown_ = {done->detail_px, done->camera, done->height};
        }
    } else if (renderer_->field_upload_pending()) {
        continue_field_upload(std::chrono::steady_clock::now());
    }
    if (drag_button_ >= 0 || compute_.view_busy() || compute_.busy() || !view_fields_stale()) return;
    const float detail = effective_detail();
    const render::Camera now = camera();
    const int height = drawing_area().pixels.y;
    if (detail == 0) {
        if (!model_->fields->has_curvature()) return;  // the worker is completing them
        renderer_->update_fields(*model_->mesh, *model_->fields, model_->feature_size);
        shown_ = {0, now, height};
        return;
    }
    compute_.request_view(
        {model_->mesh, model_->fields, model_->detail, face_clusters_, now, height, detail, {}, nullptr});
}

// New fields reach the GPU in slices over several frames, each frame's
// share a quarter of the median frame (at least 4 ms): sent at once, a
// 17.8M-face mesh's 890 MB held one frame for half a second on llvmpipe
// (MeshBuffers::begin_upload; docs/gpu.md).
void ViewerApp::continue_field_upload(std::chrono::steady_clock::time_point since) {
    send_slices(since, [&](size_t bytes) { return renderer_->continue_field_upload(bytes); });
    landing_ms_.push_back(1e3f * float(seconds_since(since)));
    redraw_frames_ = 2;  // the frames go on until the new fields are drawn
}

// One frame's share of sending to the GPU: 8 MiB slices (send returns true after the last) until
// none is left or a quarter of the median frame (at least 4 ms) since `since` is spent.
bool ViewerApp::send_slices(std::chrono::steady_clock::time_point since, const std::function<bool(size_t)>& send) {
    const double budget_s = std::max(0.004, 0.25e-3 * double(median(frame_ms_)));
    while (!send(size_t(8) << 20))
        if (seconds_since(since) >= budget_s) return false;
    return true;
}

bool ViewerApp::view_fields_stale() const {
    if (!model_ || !renderer_->mesh()) return false;
    const float detail = effective_detail();
    if (detail != shown_.detail) return true;
    if (detail == 0) return false;
    const render::Camera now = camera();
    const int height = drawing_area().pixels.y;
    const glm::vec3 pivot = orbit_.pivot();
    const auto pixel_at_pivot = [&](const render::Camera& c, int h) {
        return glm::length(c.eye() - pivot) * std::tan(glm::radians(0.5f * c.fov_y_deg)) / float(std::max(h, 1));
    };
    const float ratio = pixel_at_pivot(now, height) / pixel_at_pivot(shown_.camera, shown_.height);
    const float turn = glm::dot(glm::normalize(now.eye() - pivot), glm::normalize(shown_.camera.eye() - pivot));
    return !(ratio < 1.1f && ratio > 1.0f / 1.1f && turn > std::cos(glm::radians(10.0f)));
}

void ViewerApp::draw_frame() {
    const auto t_begin = std::chrono::steady_clock::now();
    const glm::ivec2 fb = window_->framebuffer_size();
    if (fb.x <= 0 || fb.y <= 0) return;  // minimised

    // The drawing, exactly as `kappa render` draws it (in the renderer's own
    // framebuffer), then copied into the window right of the panel.
    const Area area = drawing_area();
    // While the mouse moves the model and full-quality frames are slow
    // (software rendering), draw without multisampling; the still image
    // after the release is full quality again.
    render::RenderSettings settings = state_.settings;
    settings.detail = shown_.detail;  // the scale of the fields on the GPU (line occlusion tolerance)
    const bool reduced =
        panel_.fast_while_moving && settings.msaa && ((drag_button_ >= 0 && full_quality_slow_) || quick_frame_);
    if (reduced) settings.msaa = false;
    if (quick_frame_) redraw_frames_ = std::max(redraw_frames_, 1);
    quick_frame_ = false;
    // The view moves while dragging and in any frame whose view differs from the last one's.
    const render::Camera view = camera();
    const bool moving = drag_button_ >= 0 || view.view != last_view_.view || view.fov_y_deg != last_view_.fov_y_deg ||
                        area.pixels != last_view_size_;
    last_view_ = view, last_view_size_ = area.pixels;
    renderer_->set_view_moving(moving);
    if (moving && settings.hatching != render::Hatching::None) redraw_frames_ = std::max(redraw_frames_, 1);
    renderer_->render_offscreen(view, settings, area.pixels.x, area.pixels.y);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glViewport(0, 0, fb.x, fb.y);
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, renderer_->offscreen_framebuffer());
    const int x0 = fb.x - area.pixels.x;
    glBlitFramebuffer(0, 0, area.pixels.x, area.pixels.y, x0, 0, fb.x, area.pixels.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);

    // The UI on top.
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    PanelInfo info;
    info.model = model_ ? &*model_ : nullptr;
    info.map_range = renderer_->mesh() ? renderer_->mesh()->map_range(state_.settings.colormap) : 1.0f;
    info.upload_s = upload_s_;
    info.first_frame_s = first_frame_s_;
    info.computing = compute_.busy() || first_view_pending_;
    // A first view's fields: no fraction known; then its slices to the GPU.
    info.progress = compute_.busy() ? compute_.progress() : landing_ ? landing_->upload_progress() : -1.0f;
    info.stage = compute_.busy() ? compute_.stage()
                 : landing_       ? "sending the view to the GPU"
                                  : "detail fields for the view";
    info.frame_ms = median(frame_ms_);
    info.gl = window_->description();
    const float scale = window_->content_scale();
    if (panel_.visible) handle_panel(draw_panel(state_, panel_, info, scale));
    draw_help_window(&panel_.help, scale);
    draw_progress_overlay(info, scale);
    ImGui::Render();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fb.x, fb.y);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (pending_screenshot_) {
        save_screenshot(pending_screenshot_->value, pending_screenshot_->flag);
        pending_screenshot_.reset();
    }
    if (model_ && first_view_pending_) ++(landing_ ? landing_frames_ : frames_before_first_view_);
    if (model_ && !first_view_pending_ && !first_frame_drawn_) {
        glFinish();
        first_frame_drawn_ = true;
        first_frame_s_ = float(seconds_since(options_.start));
        std::printf("%s: %zu vertices, %zu faces; first frame at %.3f s (load %.3f s, curvature %.3f s, "
                    "upload %.3f s)",
                    model_->path.empty() ? "built-in model" : model_->path.c_str(), model_->mesh->vertex_count(),
                    model_->mesh->face_count(), first_frame_s_, model_->load_s, model_->fields_s, upload_s_);
        if (frames_before_first_view_ > 0)
            std::printf("; %zu frames drawn while the worker made its fields, %zu while it was sent to the GPU "
                        "in %zu slices (longest share %.1f ms)",
                        frames_before_first_view_, landing_frames_, landing_slices_, landing_longest_ms_);
        std::printf("\n");
        std::fflush(stdout);
    }
    window_->swap_buffers();
    compute_.frame_drawn();

    const float ms = float(seconds_since(t_begin) * 1000.0);
    frame_ms_.push_back(ms);
    if (frame_ms_.size() > 31) frame_ms_.pop_front();
    if (!reduced && state_.settings.msaa) full_quality_slow_ = ms > 33.0f;
    if (model_) (drag_button_ >= 0 ? moving_ms_ : still_ms_).push_back(ms);
}

}  // namespace kappa::viewer
