// One view of the mesh as a vector drawing (SVG or PDF): the surface is
// rendered without lines (its depth decides what the strokes hide, and its
// picture becomes the underlay unless the surface is plain: --shading none,
// no colour map), then the hatching strokes (render/hatching/hatch_streamlines.h) and
// the visible line strokes (render/vector/strokes.h) are made and written
// (render/vector/vector_drawing.h), hatching first, under the lines.
#pragma once

#include "render/renderer.h"
#include "render/vector/strokes.h"
#include "render/vector/vector_drawing.h"

#include <string>

namespace kappa::render {

VectorDrawing draw_vector_view(Renderer& renderer, const Camera& camera, const RenderSettings& settings, int width,
                               int height, const StrokeSource& source, Image& underlay);

// draw_vector_view, then write_svg or write_pdf. Throws std::runtime_error "PATH: reason".
void write_vector_view(Renderer& renderer, const Camera& camera, const RenderSettings& settings, int width, int height,
                       const StrokeSource& source, VectorFormat format, const std::string& path);

}  // namespace kappa::render
