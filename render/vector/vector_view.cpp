#include "render/vector/vector_view.h"

#include "render/vector/plotter.h"
#include "render/vector/stroke_cleanup.h"

#include <iterator>

namespace kappa::render {

VectorDrawing draw_vector_view(Renderer& renderer, const Camera& camera, const RenderSettings& settings, int width,
                               int height, const StrokeSource& source, Image& underlay) {
    RenderSettings surface_only = settings;
    surface_only.lines = LineSelection{false, false, false, false};
    surface_only.vectors = 0;
    surface_only.hidden_lines = false;
    surface_only.hatching = Hatching::None;  // hatching comes as strokes
    const bool plain = settings.shading == Shading::None && settings.colormap == ColorMap::None && !settings.colorbar;
    if (plain) surface_only.background = glm::vec4(0);  // the underlay is left out
    underlay = render_to_image(renderer, camera, surface_only, width, height);
    SurfaceDepth depth{width, height, renderer.surface_depth()};

    VectorDrawing drawing;
    drawing.width = width, drawing.height = height;
    drawing.line_width = settings.line_width;
    drawing.line_color = settings.line_color;
    drawing.background = settings.background;
    drawing.underlay = plain ? nullptr : &underlay;
    if (renderer.mesh()) {
        drawing.strokes = renderer.hatch_strokes(camera, settings, width, height);
        std::vector<Stroke> lines = extract_strokes(source, camera, renderer.mesh()->bounds(), settings, depth);
        drawing.strokes.insert(drawing.strokes.end(), std::make_move_iterator(lines.begin()),
                               std::make_move_iterator(lines.end()));
    }
    simplify_strokes(drawing.strokes, settings.simplify);
    drop_short_strokes(drawing.strokes, settings.min_stroke);
    if (settings.plotter) {
        drawing.strokes = plotter_paths(std::move(drawing.strokes));
    } else {
        drawing.taper = settings.taper;
        drawing.width_by_strength = settings.width_by_strength;
    }
    if (renderer.mesh()) attach_surface_points(drawing.strokes, camera, renderer.mesh()->bounds(), depth);
    return drawing;
}

void write_vector_view(Renderer& renderer, const Camera& camera, const RenderSettings& settings, int width, int height,
                       const StrokeSource& source, VectorFormat format, const std::string& path) {
    Image underlay;
    const VectorDrawing drawing = draw_vector_view(renderer, camera, settings, width, height, source, underlay);
    if (format == VectorFormat::Svg) write_svg(path, drawing);
    else write_pdf(path, drawing);
}

}  // namespace kappa::render
