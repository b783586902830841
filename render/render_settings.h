// Everything that decides how a mesh is drawn: one structure shared by
// `kappa render` (command-line options, conventions.md) and the viewer
// (its UI edits the same fields). Plain data, no OpenGL.
#pragma once

#include "geometry/mesh/mesh.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <optional>
#include <string>
#include <vector>

namespace kappa::render {

enum class Shading { None, Lambert, Toon, Hemisphere, ToonBW, Gooch };
enum class ColorMap { None, K1, K2, Mean, Gaussian, Principal, DCurv };
enum class Hatching { None, Min, Max, Cross };
// How hatching is drawn (--hatch-style): evenly spaced streamlines traced on
// the CPU over a field read back from the GPU (render/hatching/hatch_streamlines.h;
// attached to the surface, and the only style of vector output), or strokes
// drawn by the surface pass on the GPU (shaders/hatching/shader_hatching.glsl:
// no readback, frame-rate cheap, fixed to the window). The viewer draws the
// shader style while the view moves and the streamlines once it rests.
enum class HatchStyle { Streamlines, Shader };
// Where the lines of --lines (all but creases and boundaries) are extracted:
// compute passes (GL 4.3; render/lines/segment_buffer.h), geometry shaders
// (gpu), or the CPU (render/lines/cpu_lines.h). auto = the CPU when the GL is
// a software renderer (llvmpipe), compute passes on a hardware GL 4.3 or
// later, geometry shaders otherwise (Renderer::line_path).
enum class LineExtraction { Auto, Compute, Gpu, Cpu };

// Per-vertex direction glyphs (--vectors), as bits.
enum VectorGlyph { kGlyphNormal = 1, kGlyphPrincipal1 = 2, kGlyphPrincipal2 = 4, kGlyphAsymptotic = 8, kGlyphView = 16 };

struct LineSelection {
    bool contours = true;     // occluding contours: zeros of n.v
    bool suggestive = true;   // suggestive contours: zeros of kr with Dw kr > threshold / fs^2
    bool boundaries = false;  // open mesh boundaries
    bool creases = true;      // visible sharp edges (geometry/mesh/creases.h)
    // View-independent curvature lines (shaders/lines/curvature_lines_geom.glsl).
    bool ridges = false;      // maxima of the larger-magnitude curvature along its direction, > 0
    bool valleys = false;     // the same, < 0
    bool parabolic = false;   // K = 0
    bool mean_zero = false;   // H = 0
    bool isophotes = false;   // levels of n.l (shaders/lines/level_lines_geom.glsl)
    bool topo = false;        // levels of the height along y
    bool silhouette = false;  // the exterior silhouette only: contours that border the background
    // View-dependent lines beyond contours (shaders/lines/isolines_geom.glsl, shaders/lines/view_ridges_geom.glsl).
    bool apparent_ridges = false;        // Judd et al. 2007: maxima of the view-dependent curvature
    bool suggestive_highlights = false;  // zeros of kr where Dw kr < -threshold / fs^2 (DeCarlo and Rusinkiewicz 2007)
    bool principal_highlights = false;   // where w lies along the principal direction of smaller curvature on ridges and valleys
    bool dwkr = false;                   // Dw kr = the suggestive-contour threshold
    bool curvature_lines() const { return ridges || valleys || parabolic || mean_zero; }
    bool view_ridges() const { return apparent_ridges || principal_highlights; }
    bool any() const {
        return contours || suggestive || boundaries || creases || curvature_lines() || isophotes || topo || silhouette ||
               view_ridges() || suggestive_highlights || dwkr;
    }
    // Contours are extracted for either; with silhouette alone only the exterior ones are kept.
    bool any_contours() const { return contours || silhouette; }
};

struct RenderSettings {
    LineSelection lines;
    float line_width = 2.0f;           // pixels, constant at any zoom
    bool hidden_lines = false;         // also draw the hidden parts of the lines, dashed and light
    int vectors = 0;                   // glyphs: bits of VectorGlyph (shaders/lines/vectors_geom.glsl)
    float sc_threshold = 0.05f;        // dimensionless (rtsc's default); applied as Dw kr > s / fs^2
    float rv_threshold = 1.5f;         // dimensionless; ridges and valleys where |kmax| > S / fs
    float ar_threshold = 1.0f;         // dimensionless; apparent ridges where the view-dependent curvature > S / fs
    float sh_threshold = 0.1f;         // dimensionless; suggestive highlights where -Dw kr > s / fs^2
    float ph_threshold = 0.2f;         // dimensionless; principal highlights where (kmax^2 - kmin^2) n.v > s / fs^2
    int isophote_count = 4;            // isophotes at n.l = (k - 1/2) / N, k = 1..N
    int topo_count = 12;               // topographic lines: N heights evenly across the bounding sphere
    bool fade = true;                  // fade weak suggestive contours towards the threshold
    float detail = 12.0f;              // pixels: lines follow the surface at this scale (0 = off: the raw 1-ring fields)
    float crease_angle = -1.0f;        // degrees between faces that make a sharp edge; -1 auto, 0 off (geometry/mesh/creases.h)
    glm::vec3 line_color{0, 0, 0};

    Shading shading = Shading::Lambert;
    glm::vec3 light_dir{-0.35f, 0.45f, 1.0f};  // towards the light, camera coordinates (x right, y up, z to the viewer)
    bool light_on_model = false;       // light_dir is in model coordinates instead: the light turns with the model
    ColorMap colormap = ColorMap::None;
    bool colorbar = false;             // legend of the colour map in the image
    Hatching hatching = Hatching::None;
    float hatch_spacing = 4.0f;        // pixels between strokes in the darkest tone
    float hatch_stroke_length = 16.0f; // pixels
    float hatch_stroke_width = 1.25f;  // pixels
    HatchStyle hatch_style = HatchStyle::Streamlines;

    // Vector output (-o .svg/.pdf): clean-up of the strokes (render/vector/stroke_cleanup.h, render/vector/plotter.h).
    float min_stroke = 0;              // pixels: visible paths shorter than this are dropped
    float simplify = 0.25f;            // pixels: paths simplified within this distance
    float taper = 0;                   // pixels: stroke ends thin out over this length
    bool width_by_strength = false;    // fading shown as stroke width instead of opacity
    bool plotter = false;              // one pen width, no overlaps, joined, ordered for pen travel

    glm::vec4 background{1, 1, 1, 1};  // straight RGBA; alpha 0 = transparent
    bool msaa = true;                  // 4x multisampling of the surface pass
    LineExtraction line_extraction = LineExtraction::Auto;
    bool cull_clusters = true;         // skip clusters that cannot hold a line (same image; off for tests, benchmarks)
};

// settings.light_dir as a unit vector; straight towards the viewer when it is zero.
glm::vec3 unit_light_direction(const RenderSettings& settings);

// Names as on the command line (conventions.md). parse_* return nullopt for
// an unknown word.
const std::vector<std::string>& shading_names();
const std::vector<std::string>& colormap_names();
const std::vector<std::string>& hatching_names();
const std::vector<std::string>& hatch_style_names();
// Every line kind: its word in --lines and its flag. The one list behind
// line_names, parse_lines and to_string (and the viewer's panel and keys).
struct LineKind {
    std::string name;  // "apparent-ridges"
    bool LineSelection::*flag;
};
const std::vector<LineKind>& line_kinds();
const LineKind* find_line_kind(const std::string& name);
// The kinds' names, then none.
const std::vector<std::string>& line_names();
std::optional<Shading> parse_shading(const std::string& s);
std::optional<ColorMap> parse_colormap(const std::string& s);
std::optional<Hatching> parse_hatching(const std::string& s);
std::optional<HatchStyle> parse_hatch_style(const std::string& s);
// Whether a frame with these settings draws its hatching on the GPU (render/hatching/shader_hatching.h).
inline bool shader_hatching(const RenderSettings& s) {
    return s.hatching != Hatching::None && s.hatch_style == HatchStyle::Shader;
}
// "contours,suggestive", "none"; nullopt for unknown or repeated words.
std::optional<LineSelection> parse_lines(const std::string& list);
// "normal,principal1,principal2,asymptotic,view" (any of them) or "none": RenderSettings::vectors.
std::optional<int> parse_vectors(const std::string& list);
const std::vector<std::string>& vector_names();
// "off" (0) or a size in pixels in (0, 1000]: RenderSettings::detail.
std::optional<float> parse_detail(const std::string& s);
// "auto" (-1), "off" or "0" (0), or degrees in (0, 180): RenderSettings::crease_angle.
std::optional<float> parse_crease_angle(const std::string& s);
// The crease angle to use for this mesh: auto resolved (creases.h).
float resolved_crease_angle(float setting, const Mesh& mesh);
// "white", "transparent", "#rrggbb" (also "black").
std::optional<glm::vec4> parse_background(const std::string& s);
// "black", "white" or "#rrggbb": an opaque colour (RenderSettings::line_color).
std::optional<glm::vec3> parse_color(const std::string& s);

std::string to_string(Shading s);
std::string to_string(ColorMap m);
std::string to_string(Hatching h);
std::string to_string(HatchStyle h);
std::string to_string(const LineSelection& l);

}  // namespace kappa::render
