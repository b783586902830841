// A drawing made of strokes (render/vector/strokes.h), written as SVG or PDF:
// strokes in image pixels, one group per line type, round caps and joins,
// fading as opacity, and optionally a raster image underneath (shading or a
// colour map; none for pure vectors).
#pragma once

#include "render/image/image.h"
#include "render/vector/strokes.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <optional>
#include <string>
#include <vector>

namespace kappa::render {

struct VectorDrawing {
    int width = 0, height = 0;          // pixels; SVG user units and PDF points are pixels
    std::vector<Stroke> strokes;
    float line_width = 2;               // pixels
    glm::vec3 line_color{0, 0, 0};
    glm::vec4 background{1, 1, 1, 1};   // straight RGBA; alpha 0: none
    const Image* underlay = nullptr;    // drawn under the strokes when set (same size)
    float taper = 0;                    // pixels: stroke ends thin out over this length (0: none)
    bool width_by_strength = false;     // fading shown as width (full ink) instead of opacity
};

// A stroke cut into pieces of one opacity and one width each (both rounded
// to 1/16), consecutive pieces sharing their end points: SVG and PDF paths
// have one of each. Width: the stroke's width (or drawing.line_width) times
// the taper (tapered_width, render/hatching/stroke_pass.h: from 0.2 at a path's end to
// 1 at `taper` pixels from it, the stroke's own taper or the drawing's; ends
// are resampled every pixel there) times the strength when width_by_strength.
// Where two pieces meet, neither has a round cap: round caps overlap there,
// and two translucent caps over each other ink more than either (beads along
// a fading line). Their ends are butt, and a piece's own round cap at a
// stroke's end is drawn as a half disc beyond it (piece_cap).
struct StrokePiece {
    std::vector<glm::vec2> points;
    float opacity = 1;
    float width = 1;  // pixels
    bool round_start = true, round_end = true;  // false where it joins the piece before / after
};

// The half disc of diameter width beyond a piece's end (at_start: its first
// point): the end point, the unit direction pointing out of the piece, and
// the two corners (end +- half width across).
struct PieceCap {
    glm::vec2 centre, outward, left, right;
};
PieceCap piece_cap(const StrokePiece& piece, bool at_start);
std::vector<StrokePiece> stroke_pieces(const Stroke& stroke, const VectorDrawing& drawing);

// The order of the layers in a file: hatching at the bottom, then the line
// types in LineType order.
std::vector<LineType> layer_order();
int layer_rank(LineType type);  // its position in layer_order()

enum class VectorFormat { Svg, Pdf };
// From the file's extension (.svg, .pdf, any case); nullopt for anything else.
std::optional<VectorFormat> vector_format_for(const std::string& path);

// Hand-written SVG 1.1: an Inkscape layer (<g inkscape:groupmode="layer">)
// per line type, the underlay as an embedded PNG. Throws std::runtime_error
// "PATH: reason".
void write_svg(const std::string& path, const VectorDrawing& drawing);
// PDF through cairo (one page of width x height points). Throws as write_svg.
void write_pdf(const std::string& path, const VectorDrawing& drawing);

}  // namespace kappa::render
