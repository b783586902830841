// Scripted runs of the viewer: the steps of --script (input_script.h), then
// --frames N frames and the --screenshot, one call per frame.
#include "app/viewer/viewer_app.h"

#include <glm/common.hpp>

namespace kappa::viewer {

namespace {

bool same_smoothing(const SmoothingOptions& a, const SmoothingOptions& b) {
    return a.normals == b.normals && a.curvature == b.curvature && a.dcurv == b.dcurv && a.automatic == b.automatic &&
           a.estimator == b.estimator;
}

}  // namespace

bool ViewerApp::script_step() {
    if (exit_status_ != 0) return false;  // an error already ended the run
    if (!model_) return true;             // the first mesh is still loading: draw its progress
    const auto& steps = options_.script;
    while (step_ < steps.size()) {
        const ScriptStep& s = steps[step_];
        switch (s.kind) {
        case ScriptStep::Frames:
            if (frames_left_ == 0) frames_left_ = s.count;
            if (--frames_left_ == 0) ++step_;
            return true;
        case ScriptStep::WaitCompute:
            if (compute_.busy() || compute_.view_busy() || first_view_pending_ || view_fields_stale() ||
                renderer_->field_upload_pending())
                return true;
            break;
        case ScriptStep::WaitHatching:
            if (state_.settings.hatching != render::Hatching::None &&
                state_.settings.hatch_style == render::HatchStyle::Streamlines && !renderer_->drew_streamlines())
                return true;
            break;
        case ScriptStep::Drag:
            // The same handlers as real mouse events: press, one move a frame, release.
            if (drag_moves_ == 0) mouse_button(s.button, true, s.from);
            ++drag_moves_;
            cursor_moved(glm::mix(s.from, s.to, float(drag_moves_) / float(s.count)));
            if (drag_moves_ < s.count) return true;
            mouse_button(s.button, false, s.to);
            drag_moves_ = 0;
            ++step_;
            return true;
        case ScriptStep::Scroll: scrolled(s.amount, s.from); break;
        case ScriptStep::Key: {
            const Shortcut* k = find_shortcut(s.name);
            apply(k->action, k->line);
            break;
        }
        case ScriptStep::Set: {
            const SmoothingOptions before = state_.smoothing;
            const float crease_before = state_.settings.crease_angle;
            if (auto error = assign_setting(state_, s.name, s.value)) report(*error, true);
            if (state_.settings.crease_angle != crease_before)  // the split changes: read the mesh again
                open_mesh(model_->path);
            else if (!same_smoothing(before, state_.smoothing))
                compute_.recompute(*model_, state_.smoothing);
            break;
        }
        case ScriptStep::Panel: panel_.visible = s.flag; break;
        case ScriptStep::Screenshot:
            pending_screenshot_ = s;  // taken at the end of this frame
            ++step_;
            return true;
        case ScriptStep::SaveView: save_view(s.value); break;
        case ScriptStep::LoadView: load_view(s.value); break;
        case ScriptStep::Open: open_mesh(s.value); break;
        }
        ++step_;
        if (exit_status_ != 0) return false;
    }
    // After the script: --frames N, the last one saved to --screenshot.
    if (!final_frames_started_) {
        final_frames_started_ = true;
        frames_left_ = options_.frames;
    }
    if (frames_left_ <= 0) return false;
    if (--frames_left_ == 0 && !options_.screenshot.empty()) {
        ScriptStep shot;
        shot.kind = ScriptStep::Screenshot;
        shot.value = options_.screenshot;
        shot.flag = true;
        pending_screenshot_ = shot;
    }
    return true;
}

}  // namespace kappa::viewer
