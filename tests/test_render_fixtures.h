// Shared by the render tests: one headless GL context per test process,
// analytic surface fields for shapes whose curvature is known exactly
// (conventions.md), and helpers that look at rendered images.
#pragma once

#include <string>

#include "geometry/mesh/mesh.h"
#include "geometry/surface_fields.h"
#include "render/camera/camera.h"
#include "render/image/image.h"
#include "render/render_settings.h"
#include "render/renderer.h"

#include <functional>

namespace kappa::test {

// The process's headless context and a renderer on it (created on first use).
render::Renderer& renderer();

// bunny.ply (holes in its base: back faces show through them) and its
// fields, uploaded to renderer(); returns its bounding sphere.
render::BoundingSphere upload_shared_bunny();

// Exact fields: sphere of radius R centred at the origin (n = p/R, k1 = k2 =
// 1/R, C = 0); torus around z (R major, r minor: curvature 1/r along the
// tube, cos v / (R + r cos v) along the big circle, c = C122 the only
// non-zero entry of C); flat z = 0 grid (all zero).
SurfaceFields sphere_fields(const Mesh& mesh, float radius);
SurfaceFields torus_fields(const Mesh& mesh, float major, float minor);
SurfaceFields flat_fields(const Mesh& mesh);

// The command line of `kappa render ARGS` (the executable this build made).
inline std::string kappa_render(const std::string& args) { return std::string(KAPPA_EXE) + " render " + args; }

// Settings that show only dark lines on white (conventions.md: tests find
// lines as dark pixels), no MSAA, line width 2.
render::RenderSettings lines_only(render::LineSelection lines);

// Uploads mesh + fields (feature size fs) and renders a width x height image.
render::Image render(const Mesh& mesh, const SurfaceFields& fields, float fs, const render::Camera& camera,
                     const render::RenderSettings& settings, int width = 256, int height = 256);

// Pixels whose colour differs by more than a quarter of full ink (64 of 255) in a channel.
size_t differing_pixels(const render::Image& a, const render::Image& b);
// The largest difference of any channel of two images of one size (0..255).
int largest_difference(const render::Image& a, const render::Image& b);
// What merging line segments on screen (render/lines/screen_merge.h: within 0.2 px
// and 1/64 opacity) may change in a pixel of a line drawing on software GL:
// box-filtered coverage moves by at most the distance its centre line
// moves, so 0.2 + 1/64 of full ink, 55 of 255. A line drawn or lost changes
// its pixels by its full ink.
constexpr int kScreenMergeTolerance = 55;

// A pixel is "ink" when its darkest channel is below 128 (on white paper).
bool is_ink(const render::Rgba& c);
size_t count_ink(const render::Image& image);

// Where a model point lands in the image: (x, y) in pixels, y down, pixel
// centres at .5 (for comparing with Image::at(int(x), int(y))).
glm::vec2 project(const render::Camera& camera, const render::BoundingSphere& bounds, glm::vec3 point, int width,
                  int height);

// Writes the image as a PNG under $KAPPA_TEST_PNG_DIR when set (to look at).
void maybe_save(const render::Image& image, const std::string& name);

}  // namespace kappa::test
