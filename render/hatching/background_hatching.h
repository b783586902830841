// Streamline hatching for an interactive viewer, traced without blocking
// it: at rest, a view's hatching field is drawn and read back once on the GL
// thread, its streamlines (render/hatching/hatch_streamlines.h) are traced on
// a worker thread, and they are drawn from the first frame after they are
// ready for that very view. Until then, and whenever the view moves, the
// frame is hatched by the GPU (--hatch-style shader, shaders/hatching/shader_hatching.glsl).
#pragma once

#include "render/hatching/hatch_field.h"
#include "render/render_settings.h"
#include "render/vector/strokes.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <functional>
#include <future>
#include <vector>

namespace kappa::render {

// Everything the streamlines of a frame depend on: the same key, the same strokes.
struct HatchViewKey {
    glm::mat4 mvp{1.0f};
    glm::vec2 viewport{0.0f};
    glm::vec3 light{0.0f};  // towards the light, camera coordinates, this frame
    Hatching hatching = Hatching::None;
    float spacing = 0, stroke_width = 0;
    uint64_t fields_version = 0;
    bool operator==(const HatchViewKey& o) const;
};

class BackgroundHatching {
public:
    ~BackgroundHatching();
    // The strokes of `key`'s view when they have been traced, else null.
    const std::vector<Stroke>* strokes_for(const HatchViewKey& key);
    // Whether a tracing is under way (a frame should come soon to show it).
    bool pending() const { return job_.valid(); }
    // Traces `field` from `seeds` (window pixels) with `settings`' hatching on a worker thread.
    // Does nothing while another tracing is under way.
    void start(const HatchViewKey& key, HatchField field, std::vector<glm::vec2> seeds, const RenderSettings& settings);
    // Called on the worker thread when a tracing ends (e.g. to wake a
    // viewer waiting for events: glfwPostEmptyEvent).
    void set_on_done(std::function<void()> on_done) { on_done_ = std::move(on_done); }

private:
    std::future<std::vector<Stroke>> job_;
    HatchViewKey job_key_, done_key_;
    std::vector<Stroke> done_;
    bool have_done_ = false;
    std::function<void()> on_done_;
};

// The streamlines of a view's hatching field (the CPU half of Renderer::hatch_strokes):
// max along d1, min along d2, cross both (d2 in the darker tones), traced at once.
std::vector<Stroke> trace_view_hatching(const HatchField& field, const std::vector<glm::vec2>& seeds,
                                        const RenderSettings& settings);

}  // namespace kappa::render
