// The Python module `kappa`: curvature and line drawings from numpy arrays.
// One file per area: io.cpp, curvature.cpp, render.cpp, batch.cpp.
#include "bindings.h"

using namespace kappa::python;
namespace cli = kappa::cli;

PYBIND11_MODULE(kappa, m) {
    m.doc() = R"(kappa: curvature (Rusinkiewicz 2004) and line drawings of triangle meshes.

    V, F = kappa.load_mesh("bunny.ply")
    fields = kappa.curvature(V, F, smooth="auto")      # normals, k1, k2, d1, d2, C, flags
    image = kappa.render(V, F, camera={"view": (30, 20)}, size=(512, 384), shading="none")
    lines = kappa.strokes(V, F, lines="contours,suggestive")
    report = kappa.batch("jobs.txt", shard=(0, 4))     # as `kappa batch jobs.txt --shard 0/4`

Options are the command line's, with '-' spelled '_' (docs/python.md).)";
    // Usage errors raised in C++ after parsing (checks of options together).
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const cli::UsageError& e) {
            PyErr_SetString(PyExc_ValueError, keyword_message(e.what()).c_str());
        }
    });
    def_io(m);
    def_curvature(m);
    def_render(m);
    def_batch(m);
    def_settings(m);
    def_ink(m);
}
