// kappa.curvature: the fields of `kappa curvature`, as numpy arrays.
#include "bindings.h"

#include "geometry/parallel/parallel.h"
#include "geometry/surface_analysis.h"

#include <pybind11/stl.h>

namespace kappa::python {

namespace {

// The curvature options (--estimator, --smooth, --smooth-*) from keywords.
SmoothingOptions smoothing_options(const py::object& smooth, const py::object& estimator, const py::dict& widths) {
    py::dict words_of;
    if (!smooth.is_none()) {
        if (py::isinstance<py::str>(smooth)) {
            words_of["smooth"] = smooth;
        } else {  // (normals, curvature, dcurv) widths
            const auto w = smooth.cast<std::vector<py::object>>();
            if (w.size() != 3) throw py::value_error("smooth expects 'auto', 'off' or three widths (normals, curvature, dcurv)");
            words_of["smooth_normals"] = w[0], words_of["smooth_curvature"] = w[1], words_of["smooth_dcurv"] = w[2];
        }
    }
    words_of["estimator"] = estimator;
    for (const auto& [key, value] : widths) words_of[key] = value;
    SmoothingOptions options;
    cli::Parser p("curvature", "", "");
    p.smoothing(options);
    parse_words(p, option_words(words_of));
    return options;
}

// Sets kappa's worker threads for one call (0 or None: all cores).
class ThreadCount {
public:
    explicit ThreadCount(const py::object& threads) : before_(thread_count()) {
        if (threads.is_none()) return;
        const int n = threads.cast<int>();
        if (n < 0 || n > 4096) throw py::value_error("threads expects an integer in [0, 4096], got " + std::to_string(n));
        set_thread_count(unsigned(n));
    }
    ~ThreadCount() { set_thread_count(before_); }

private:
    unsigned before_;
};

py::dict fields_dict(SurfaceFields&& f) {
    const auto n = py::ssize_t(f.size());
    py::dict out;
    out["normals"] = take_array<glm::vec3, float>(std::move(f.normals), {n, 3});
    out["k1"] = take_array<float, float>(std::move(f.k1), {n});
    out["k2"] = take_array<float, float>(std::move(f.k2), {n});
    out["d1"] = take_array<glm::vec3, float>(std::move(f.d1), {n, 3});
    out["d2"] = take_array<glm::vec3, float>(std::move(f.d2), {n, 3});
    out["C"] = take_array<glm::vec4, float>(std::move(f.dcurv), {n, 4});
    out["flags"] = take_array<uint8_t, uint8_t>(std::move(f.flags), {n});
    out["smoothing"] = py::make_tuple(f.smoothing.normals, f.smoothing.curvature, f.smoothing.dcurv);
    return out;
}

}  // namespace

void def_curvature(py::module_& m) {
    m.def(
        "curvature",
        [](const py::handle& V, const py::handle& F, const py::object& smooth, const py::object& estimator,
           const py::object& threads, const py::kwargs& widths) {
            Mesh mesh = mesh_from_arrays(V, F);
            const SmoothingOptions options = smoothing_options(smooth, estimator, widths);
            ThreadCount count(threads);
            SurfaceFields fields;
            {
                py::gil_scoped_release unlocked;
                fields = compute_surface_fields(mesh, options);
            }
            return fields_dict(std::move(fields));
        },
        py::arg("V"), py::arg("F"), py::arg("smooth") = py::none(), py::arg("estimator") = "rusinkiewicz",
        py::arg("threads") = py::none(),
        R"(Per-vertex normals, curvature and its derivative, exactly as `kappa curvature` writes them.

V: (N, 3) positions, F: (M, 3) vertex indices (any integer type).
smooth: None or 'off' (the raw estimate), 'auto' (widths from the noise level), or three
  Gaussian widths (normals, curvature, dcurv) in model units; smooth_normals=,
  smooth_curvature=, smooth_dcurv= give them one by one (as --smooth-normals ...).
estimator: as --estimator (rusinkiewicz, jet, tensor-averaging, normal-fit, points-normals-fit).
threads: worker threads for this call (None or 0: all cores); results do not depend on it.

Returns a dict of arrays named as the CSV columns: normals (N, 3), k1, k2 (N,), d1, d2 (N, 3),
C (N, 4) = (a, b, c, d), flags (N,) uint8 (the PLY's bits: 1 isolated, 2 degenerate, 4 boundary,
8 non-manifold, 16 estimator fell back), and smoothing: the widths used.
Raises kappa.MeshError for bad arrays, ValueError for bad options.)");
}

}  // namespace kappa::python
