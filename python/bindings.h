// Pieces shared by the Python module's files (one file per area: io,
// curvature, render, batch): numpy conversions and option words.
#pragma once

#include "app/cli_options.h"
#include "geometry/mesh/mesh.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace kappa::python {

namespace py = pybind11;

void def_io(py::module_& m);         // io.cpp: MeshError, load_mesh
void def_curvature(py::module_& m);  // curvature.cpp
void def_render(py::module_& m);     // render.cpp: render, strokes, write, gl_context
void def_batch(py::module_& m);      // batch.cpp: batch, read_manifest
void def_settings(py::module_& m);   // settings.cpp: settings, line_groups
void def_ink(py::module_& m);        // ink.cpp: ink_agreement

// A Mesh from V (N x 3 numbers) and F (M x 3 integers), checked like a file:
// raises kappa.MeshError (kappa::MeshLoadError) naming the problem.
Mesh mesh_from_arrays(const py::handle& V, const py::handle& F);

// The values of a vector as a numpy array of `shape` without a copy: the
// vector moves into the array's owner.
template <typename T, typename Scalar>
py::array_t<Scalar> take_array(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
    auto* owned = new std::vector<T>(std::move(values));
    py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return py::array_t<Scalar>(shape, reinterpret_cast<const Scalar*>(owned->data()), owner);
}

// A path argument: str or os.PathLike.
std::string path_text(const py::handle& path);

// Keyword arguments as command-line words: line_width=2.5 -> --line-width
// 2.5; True -> a flag, or "on" for on|off settings; False -> "off" (a flag:
// left out); lists and tuples -> comma lists (size=(w, h) -> WxH); None
// -> left out.
std::vector<std::string> option_words(const py::dict& kwargs);

// Parses words with the options declared on `parser` as the command line
// would; usage errors become ValueError (TypeError for an unknown keyword)
// with the options spelled as keywords: "line_width expects ...".
void parse_words(cli::Parser& parser, const std::vector<std::string>& words);
// A usage message with options spelled as keywords, without "kappa CMD: ".
std::string keyword_message(const std::string& usage_message);

}  // namespace kappa::python
