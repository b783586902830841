// kappa.ink_agreement: render/image/ink_agreement's measure of how much two
// line drawings agree, for tests in Python (tests/python, tests/blender).
#include <string>

#include "bindings.h"
#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"

namespace kappa::python {

namespace {

std::string shape_text(const py::array& a) { return py::str(a.attr("shape")); }

// A drawing as an Image whose ink is kappa's (is_ink): a PNG's path; an
// (h, w, 3|4) uint8 image; or an (h, w) mask, ink where true or non-zero,
// drawn black on white.
render::Image drawing(const py::handle& x, const char* name) {
    if (py::isinstance<py::str>(x) || py::hasattr(x, "__fspath__")) return render::read_png(path_text(x));
    const py::array in = py::array::ensure(x);
    const auto bad = [&](const std::string& got) {
        return py::value_error(std::string("ink_agreement: ") + name +
                               " must be an (h, w) ink mask, an (h, w, 3 or 4) uint8 image or a PNG's path, got " + got);
    };
    if (!in) throw bad("a " + std::string(py::str(py::type::of(x).attr("__name__"))));
    if (in.ndim() == 2) {
        const auto ink = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(in);
        render::Image image(int(in.shape(1)), int(in.shape(0)));
        const bool* p = ink.data();
        for (size_t i = 0; i < size_t(ink.size()); ++i) {
            const uint8_t v = p[i] ? 0 : 255;
            image.pixels[4 * i] = image.pixels[4 * i + 1] = image.pixels[4 * i + 2] = v, image.pixels[4 * i + 3] = 255;
        }
        return image;
    }
    if (in.ndim() != 3 || (in.shape(2) != 3 && in.shape(2) != 4) || in.dtype().kind() != 'u' || in.itemsize() != 1)
        throw bad("shape " + shape_text(in) + " of dtype " + std::string(py::str(in.dtype())));
    const auto rgb = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>::ensure(in);
    const size_t channels = size_t(in.shape(2)), n = size_t(in.shape(0)) * size_t(in.shape(1));
    render::Image image(int(in.shape(1)), int(in.shape(0)));
    const uint8_t* p = rgb.data();
    for (size_t i = 0; i < n; ++i)
        for (size_t c = 0; c < 4; ++c) image.pixels[4 * i + c] = c < channels ? p[channels * i + c] : 255;
    return image;
}

}  // namespace

void def_ink(py::module_& m) {
    m.def(
        "ink_agreement",
        [](const py::handle& a, const py::handle& b, float radius) {
            if (!(radius >= 0))
                throw py::value_error("ink_agreement: radius must be 0 or more, got " + std::to_string(radius));
            const render::Image x = drawing(a, "a"), y = drawing(b, "b");
            if (x.width != y.width || x.height != y.height)
                throw py::value_error("ink_agreement: the drawings differ in size (" + std::to_string(x.width) + "x" +
                                      std::to_string(x.height) + " and " + std::to_string(y.width) + "x" +
                                      std::to_string(y.height) + ")");
            return py::make_tuple(render::ink_within(x, y, radius), render::ink_within(y, x, radius));
        },
        py::arg("a"), py::arg("b"), py::arg("radius") = 2.0f,
        R"(How much two line drawings of the same size agree, as the C++ tests and benchmarks measure it
(render/image/ink_agreement.h): (the fraction of a's ink within `radius` pixels of b's ink, the
fraction of b's within radius of a's), the distance taken between pixel centres; 1.0 for a drawing
with no ink. Each drawing is an (h, w, 3 or 4) uint8 image (kappa.render's; ink: a pixel whose
darkest of r, g, b is below 128), an (h, w) mask (ink where true or non-zero) or a PNG's path.)");
}

}  // namespace kappa::python
