// kappa.render, kappa.strokes and kappa.gl_context: `kappa render`'s
// drawing (app/mesh_drawing.h) on the module's GL context (gl_session.h).
#include "bindings.h"
#include "gl_session.h"

#include "app/mesh_drawing.h"
#include "app/render_options.h"
#include "geometry/io/io_errors.h"
#include "geometry/lines/line_extraction.h"
#include "render/gl/egl_context.h"

namespace kappa::python {

namespace {

// camera: None (the default view) or a dict of --view, --eye, --target,
// --up, --fov, --xf as keywords.
app::RenderOptions render_options(const py::object& camera, const py::kwargs& settings) {
    py::dict all;
    if (!camera.is_none()) {
        if (!py::isinstance<py::dict>(camera))
            throw py::type_error("camera expects None or a dict with view=(az, el), eye, target, up, fov or xf");
        for (const auto& [key, value] : camera.cast<py::dict>()) {
            const std::string name = key.cast<std::string>();
            if (name != "view" && name != "eye" && name != "target" && name != "up" && name != "fov" && name != "xf")
                throw py::type_error("camera has no key '" + name + "' (view, eye, target, up, fov, xf)");
            all[key] = name == "xf" ? py::str(path_text(value)) : py::reinterpret_borrow<py::object>(value);
        }
    }
    for (const auto& [key, value] : settings) {
        if (all.contains(key)) throw py::type_error("'" + key.cast<std::string>() + "' given twice");
        all[key] = value;
    }
    app::RenderOptions options;
    cli::Parser p("render", "", "");
    app::add_render_options(p, options);
    parse_words(p, option_words(all));
    app::finish_render_options(p, options);  // cli::UsageError: ValueError (module.cpp)
    return options;
}

Mesh drawable_mesh(const py::handle& V, const py::handle& F) {
    Mesh mesh = mesh_from_arrays(V, F);
    if (mesh.face_count() == 0) throw MeshLoadError("F is empty: the mesh has no faces: nothing to draw");
    return mesh;
}

// with_model: also 'model_points', the surface points in the mesh's coordinates.
py::dict stroke_dict(render::Stroke&& s, const DrawingUnits* with_model) {
    const auto n = py::ssize_t(s.points.size());
    py::dict out;
    if (with_model) {
        for (glm::vec3& p : s.surface) p = with_model->to_model(p);
        out["model_points"] = take_array<glm::vec3, float>(std::move(s.surface), {n, 3});
    }
    out["type"] = std::string(line_type_name(s.type));
    out["hidden"] = s.hidden;
    out["points"] = take_array<glm::vec2, float>(std::move(s.points), {n, 2});
    out["opacity"] = take_array<float, float>(std::move(s.opacity), {n});
    out["strength"] = take_array<float, float>(std::move(s.strength), {py::ssize_t(s.strength.size())});
    out["width"] = s.width;
    return out;
}

// One view of (V, F) drawn by draw(drawing, renderer, camera, options) on
// the module's GL context, without the GIL.
template <typename Draw>
void draw_view(const py::handle& V, const py::handle& F, const py::object& camera, const py::kwargs& settings,
               Draw draw) {
    Mesh mesh = drawable_mesh(V, F);
    const app::RenderOptions o = render_options(camera, settings);
    py::gil_scoped_release unlocked;
    app::MeshDrawing drawing(std::move(mesh), o.settings, o.smoothing);
    const render::Camera view = app::make_camera(o.camera, drawing, o.size);
    CurrentRenderer current;
    draw(drawing, current.renderer(), view, o);
}

const char* kCameraDoc = R"(
camera: None for the default view, or a dict with the command line's camera options:
  {'view': (az, el)} (degrees), {'eye': (x, y, z)} (framed), {'eye': ..., 'target': ...,
  'up': ...}, {'xf': 'view.xf'}, and 'fov' (degrees) with any of them.
settings: every option of `kappa render` with '-' spelled '_': size=(w, h), lines='contours,suggestive'
  or ['contours', 'suggestive'], shading='none', detail=12 or 'off', sc_threshold=0.05,
  line_width=2.5, fade=False, hatching='cross', background='transparent', colorbar=True,
  smooth='auto', estimator='jet', ... (`kappa render --help` lists them with their defaults).
Raises kappa.MeshError for bad arrays (and an empty F), ValueError/TypeError for bad settings,
RuntimeError when no OpenGL context can be made.)";

}  // namespace

void def_render(py::module_& m) {
    m.def(
        "render",
        [](const py::handle& V, const py::handle& F, const py::object& camera, const py::kwargs& settings) {
            render::Image image;
            draw_view(V, F, camera, settings, [&](app::MeshDrawing& d, render::Renderer& r, const render::Camera& view,
                                                  const app::RenderOptions& o) {
                image = d.image(r, view, o.settings, o.size);
            });
            return take_array<uint8_t, uint8_t>(std::move(image.pixels), {image.height, image.width, 4});
        },
        py::arg("V"), py::arg("F"), py::kw_only(), py::arg("camera") = py::none(),
        (std::string(R"(Draws the mesh as `kappa render` does, headless (EGL; no display needed).

Returns the image as an (height, width, 4) uint8 array, straight RGBA, top row first: the same pixels
as `kappa render MESH -o out.png` with the same options. The GL context is made on the first call and
reused by every later one (kappa.gl_context()).
)") + kCameraDoc).c_str());
    m.def(
        "strokes",
        [](const py::handle& V, const py::handle& F, const py::object& camera, const std::string& space,
           const py::kwargs& settings) {
            if (space != "image" && space != "model")
                throw py::value_error("space expects 'image' or 'model', got '" + space + "'");
            render::VectorDrawing drawing;
            DrawingUnits units;
            draw_view(V, F, camera, settings, [&](app::MeshDrawing& d, render::Renderer& r, const render::Camera& view,
                                                  const app::RenderOptions& o) {
                render::Image underlay;  // the strokes are all that is kept
                drawing = d.vectors(r, view, o.settings, o.size, underlay);
                drawing.underlay = nullptr;
                units = d.units();
            });
            py::list out;
            for (render::Stroke& s : drawing.strokes)
                out.append(stroke_dict(std::move(s), space == "model" ? &units : nullptr));
            return out;
        },
        py::arg("V"), py::arg("F"), py::kw_only(), py::arg("camera") = py::none(), py::arg("space") = "image",
        (std::string(R"(The visible lines of a view as polylines: what `kappa render -o out.svg` writes.

Returns a list of dicts, the hatching strokes first, then the lines:
  type: the line type ('contours', 'suggestive', ..., 'hatching'),
  hidden: True for the dashed hidden parts (hidden_lines=True),
  points: (n, 2) float32 image pixels (x right, y down, (0, 0) the top-left corner),
  opacity: (n,) float32 in [0, 1] (fading), strength: (n,) float32, the test value behind fading
        (may be empty), width: pixels (0: the drawing's line_width),
  model_points (space='model' only): (n, 3) float32, where each point lies on the surface, in the
        coordinates of V (the lines' own points; hatching and plotter paths: the drawn depth under them).
The strokes are simplified (simplify=0.25 px by default) and cleaned up as in the SVG.
)") + kCameraDoc).c_str());
    m.def(
        "write",
        [](const py::handle& V, const py::handle& F, const py::handle& path, const py::object& camera,
           const py::kwargs& settings) {
            const std::string file = path_text(path);
            draw_view(V, F, camera, settings, [&](app::MeshDrawing& d, render::Renderer& r, const render::Camera& view,
                                                  const app::RenderOptions& o) { d.write(r, view, o.settings, o.size, file); });
        },
        py::arg("V"), py::arg("F"), py::arg("path"), py::kw_only(), py::arg("camera") = py::none(),
        (std::string(R"(Writes the view to path as `kappa render MESH -o PATH` does: .png, .jpg/.jpeg, .svg (the
SVG writer: a layer per line type) or .pdf, chosen by the extension. Raises RuntimeError
"PATH: reason" when the file cannot be written.
)") + kCameraDoc).c_str());
    m.def(
        "gl_context",
        [] {
            const GlStats s = gl_stats();
            py::dict out;
            out["description"] = s.description;
            out["contexts_created"] = s.contexts_created;
            out["drawings"] = s.drawings;
            return out;
        },
        R"(The module's GL context: {'description': renderer and platform ('' before the first drawing),
'contexts_created': 0 or 1 (one per process, reused by every call), 'drawings': calls that drew}.)");
    py::register_exception<render::ContextError>(m, "ContextError", PyExc_RuntimeError);
}

}  // namespace kappa::python
