#include "render/vector/strokes.h"

#include "geometry/lines/chain.h"
#include "geometry/lines/view_quantities.h"
#include "render/camera/frame_params.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace kappa::render {

namespace {

// A point of a path on screen: window pixels (GL, y up), window depth, and
// the distance from the camera plane (clip w).
struct WindowPoint {
    glm::vec2 xy;
    float depth, w;
};

WindowPoint to_window(const glm::mat4& mvp, glm::vec3 p, glm::vec2 viewport) {
    const glm::vec4 c = mvp * glm::vec4(p, 1.0f);
    const glm::vec3 ndc = glm::vec3(c) / c.w;
    return {(glm::vec2(ndc) * 0.5f + 0.5f) * viewport, ndc.z * 0.5f + 0.5f, c.w};
}

// The visibility test of shaders/lines/lines_frag.glsl at window point q.
class DepthTest {
public:
    DepthTest(const SurfaceDepth& d, const glm::mat4& projection) : d_(d), p22_(projection[2][2]), p32_(projection[3][2]) {}

    // Whether the pixel at q (clamped to the image) shows the background.
    bool background(glm::vec2 q) const {
        return at(std::clamp(int(std::floor(q.x)), 0, d_.width - 1), std::clamp(int(std::floor(q.y)), 0, d_.height - 1)) >= 1.0f;
    }

    bool visible(glm::vec2 q, float line_depth, float tolerance) const {
        const int x = std::clamp(int(std::floor(q.x)), 0, d_.width - 1);
        const int y = std::clamp(int(std::floor(q.y)), 0, d_.height - 1);
        const float line_distance = distance(line_depth);
        const float centre = at(x, y);
        if (!(centre < 1.0f) || !(line_distance > distance(centre) + tolerance)) return true;
        float farthest = centre;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                farthest = std::max(farthest, at(std::clamp(x + dx, 0, d_.width - 1), std::clamp(y + dy, 0, d_.height - 1)));
        return !(farthest < 1.0f && line_distance > distance(farthest) + tolerance);
    }

private:
    float at(int x, int y) const { return d_.depth[size_t(y) * size_t(d_.width) + size_t(x)]; }
    float distance(float window_depth) const { return p32_ / (window_depth * 2.0f - 1.0f + p22_); }
    const SurfaceDepth& d_;
    float p22_, p32_;
};

struct RunOptions {
    float scale_tolerance = 0;   // per unit of camera distance (--detail)
    bool hidden_lines = false;   // also the hidden runs
    bool exterior_only = false;  // only where background lies beside the line
    float line_width = 2;
};

// Cuts one path into its visible runs (and hidden ones when asked), appended
// to `out` in image coordinates.
void visible_runs(const Polyline& line, LineType type, const glm::mat4& mvp, glm::vec2 viewport, const DepthTest& test,
                  const RunOptions& o, std::vector<Stroke>& out) {
    Stroke run;
    run.type = type;
    enum State { kNone, kVisible, kHidden };
    State state = kNone;
    auto image_point = [&](glm::vec2 window) { return glm::vec2(window.x, viewport.y - window.y); };
    auto close_run = [&] {
        if (run.points.size() >= 2) out.push_back(run);
        run.points.clear(), run.opacity.clear(), run.strength.clear(), run.surface.clear();
    };
    auto add = [&](glm::vec2 window, float opacity, float strength, glm::vec3 surface) {
        const glm::vec2 p = image_point(window);
        if (!run.points.empty() && run.points.back() == p) return;
        run.points.push_back(p), run.opacity.push_back(opacity), run.strength.push_back(strength);
        run.surface.push_back(surface);
    };
    for (size_t i = 0; i + 1 < line.points.size(); ++i) {
        const WindowPoint a = to_window(mvp, line.points[i], viewport);
        const WindowPoint b = to_window(mvp, line.points[i + 1], viewport);
        if (a.w <= 0 || b.w <= 0) {  // behind the eye: not drawn (as emit_segment)
            close_run();
            state = kNone;
            continue;
        }
        const float tolerance = std::max(line.tolerance, o.scale_tolerance * std::max(a.w, b.w));
        const glm::vec2 along = glm::distance(a.xy, b.xy) > 1e-6f ? glm::normalize(b.xy - a.xy) : glm::vec2(1, 0);
        const glm::vec2 side(-along.y, along.x);
        const float oa = line.opacity[i], ob = line.opacity[i + 1];
        const float sa = line.strength[i], sb = line.strength[i + 1];
        const glm::vec3 pa = line.points[i], pb = line.points[i + 1];
        // The surface point under window point a + (b - a) t: perspective-correct,
        // the parameter along the segment in space is (t / wb) / ((1 - t) / wa + t / wb).
        auto surface_at = [&](float t) {
            const float s = (t / b.w) / ((1 - t) / a.w + t / b.w);
            return pa + (pb - pa) * s;
        };
        // Samples every half pixel, both ends included.
        const int steps = std::max(1, int(std::ceil(2.0f * glm::distance(a.xy, b.xy))));
        for (int k = 0; k <= steps; ++k) {
            const float t = float(k) / float(steps);
            const glm::vec2 q = a.xy + (b.xy - a.xy) * t;
            State now = test.visible(q, a.depth + (b.depth - a.depth) * t, tolerance) ? kVisible : kHidden;
            if (now == kHidden && !o.hidden_lines) now = kNone;
            if (now == kVisible && o.exterior_only) {
                const float reach = 0.5f * o.line_width + 2.0f;
                if (!test.background(q + side * reach) && !test.background(q - side * reach)) now = kNone;
            }
            if (now != state) {
                // A change: the run so far ends here, and a new one starts here.
                if (state != kNone) add(q, oa + (ob - oa) * t, sa + (sb - sa) * t, surface_at(t));
                close_run();
                state = now;
                run.hidden = state == kHidden;
            }
            // Keep the path's own vertices and the points where visibility changes.
            if (state != kNone && (k == 0 || k == steps || run.points.empty()))
                add(q, oa + (ob - oa) * t, sa + (sb - sa) * t, surface_at(t));
        }
    }
    close_run();
}

}  // namespace

std::vector<Stroke> extract_strokes(const StrokeSource& source, const Camera& camera, const BoundingSphere& bounds,
                                    const RenderSettings& settings, const SurfaceDepth& depth) {
    const FrameParams frame = FrameParams::make(camera, bounds, depth.width, depth.height);
    const LineSelection& lines = settings.lines;
    LineExtractionOptions options;
    options.contours = lines.any_contours();
    options.suggestive = lines.suggestive;
    options.boundaries = lines.boundaries;
    options.creases = lines.creases;
    options.suggestive_highlights = lines.suggestive_highlights;
    options.dwkr = lines.dwkr;
    options.ridges = lines.ridges, options.valleys = lines.valleys;
    options.parabolic = lines.parabolic, options.mean_zero = lines.mean_zero;
    options.isophotes = lines.isophotes, options.topo = lines.topo;
    options.apparent_ridges = lines.apparent_ridges, options.principal_highlights = lines.principal_highlights;
    options.ar_threshold = settings.ar_threshold, options.ph_threshold = settings.ph_threshold;
    options.hidden_creases = settings.hidden_lines;
    options.cull_back_faces = !settings.hidden_lines;  // as the line passes
    options.sc_threshold = settings.sc_threshold;
    options.sh_threshold = settings.sh_threshold;
    options.rv_threshold = settings.rv_threshold;
    options.feature_size = source.feature_size;
    options.fade = settings.fade;
    // Level lines as render/lines/line_renderer.cpp draws them.
    options.light = glm::normalize(glm::transpose(frame.normal_matrix) * camera_light_direction(settings, frame));
    options.isophote_levels = isophote_level_set(settings.isophote_count);
    options.topo_levels = topo_level_set(bounds.center.y, bounds.radius, settings.topo_count);
    static const std::vector<glm::vec3> none;
    const ViewQuantities quantities = compute_view_quantities(
        *source.mesh, *source.fields, source.contour_normals ? *source.contour_normals : none, frame.eye,
        source.feature_size);
    static const std::vector<CreaseEdge> no_creases;
    const ExtractedLines extracted = extract_lines(*source.mesh, *source.fields, quantities, frame.eye,
                                                   source.creases ? *source.creases : no_creases, options);

    const DepthTest test(depth, frame.projection);
    // As shaders/lines/isolines_geom.glsl: with --detail, contours and suggestive
    // contours may lie the detail scale behind the polygons.
    const float scale_tolerance =
        settings.detail > 0 ? settings.detail * 2.0f / (frame.projection[1][1] * frame.viewport.y) : 0.0f;
    RunOptions run_options;
    run_options.hidden_lines = settings.hidden_lines;
    run_options.line_width = settings.line_width;
    std::vector<Stroke> strokes;
    for (int type = 0; type < kLineTypeCount; ++type) {
        const bool isoline = is_view_isoline(LineType(type));
        run_options.scale_tolerance = isoline ? scale_tolerance : 0.0f;
        run_options.exterior_only = type == int(LineType::Contour) && lines.silhouette && !lines.contours;
        for (const Polyline& line : chain_segments(extracted[size_t(type)]))
            visible_runs(line, LineType(type), frame.mvp, frame.viewport, test, run_options, strokes);
    }
    return strokes;
}

void attach_surface_points(std::vector<Stroke>& strokes, const Camera& camera, const BoundingSphere& bounds,
                           const SurfaceDepth& depth) {
    if (depth.width <= 0 || depth.height <= 0) return;
    const FrameParams frame = FrameParams::make(camera, bounds, depth.width, depth.height);
    const glm::mat4 to_model = glm::inverse(frame.mvp);
    auto at = [&](int x, int y) {
        x = std::clamp(x, 0, depth.width - 1), y = std::clamp(y, 0, depth.height - 1);
        return depth.depth[size_t(y) * size_t(depth.width) + size_t(x)];
    };
    for (Stroke& s : strokes) {
        if (s.surface.size() == s.points.size()) continue;
        s.surface.clear();
        for (const glm::vec2 p : s.points) {
            const glm::vec2 window(p.x, float(depth.height) - p.y);  // GL window pixels, y up
            const int x = int(std::floor(window.x)), y = int(std::floor(window.y));
            float d = at(x, y);
            for (int dy = -1; dy <= 1 && d >= 1.0f; ++dy)
                for (int dx = -1; dx <= 1; ++dx) d = std::min(d, at(x + dx, y + dy));
            if (d >= 1.0f) d = 0.5f;  // no surface near: window depth 0.5, inside the model's depth range
            const glm::vec4 ndc(window / frame.viewport * 2.0f - 1.0f, d * 2.0f - 1.0f, 1.0f);
            const glm::vec4 m = to_model * ndc;
            s.surface.push_back(glm::vec3(m) / m.w);
        }
    }
}

}  // namespace kappa::render
