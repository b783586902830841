// kappa.load_mesh and kappa.MeshError; array checks and conversions.
#include "bindings.h"

#include "geometry/io/mesh_io.h"

#include <cmath>

namespace kappa::python {

std::string path_text(const py::handle& path) {
    return py::str(py::module_::import("os").attr("fspath")(path));
}

Mesh mesh_from_arrays(const py::handle& V, const py::handle& F) {
    const auto fail = [](const std::string& problem) { throw MeshLoadError(problem); };
    const py::array v_in = py::array::ensure(V), f_in = py::array::ensure(F);
    if (!v_in || !f_in) fail("V and F must be arrays (V: N x 3 numbers, F: M x 3 vertex indices)");
    if (v_in.ndim() != 2 || v_in.shape(1) != 3)
        fail("V must have shape (N, 3), got " + std::string(py::str(v_in.attr("shape"))));
    if (v_in.shape(0) == 0) fail("V is empty: the mesh has no vertices");
    const char kind = f_in.dtype().kind();
    if (f_in.size() > 0 && kind != 'i' && kind != 'u')
        fail("F must hold integers (vertex indices), got dtype " + std::string(py::str(f_in.dtype())));
    if (!(f_in.ndim() == 2 && f_in.shape(1) == 3) && f_in.size() > 0)
        fail("F must have shape (M, 3), got " + std::string(py::str(f_in.attr("shape"))));
    const auto v = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(v_in);
    if (!v) fail("V must hold numbers");
    Mesh mesh;
    const size_t n = size_t(v.shape(0));
    mesh.positions.resize(n);
    const float* p = v.data();
    for (size_t i = 0; i < n; ++i) {
        mesh.positions[i] = glm::vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
        if (!(std::isfinite(p[3 * i]) && std::isfinite(p[3 * i + 1]) && std::isfinite(p[3 * i + 2])))
            fail("V: vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
    if (f_in.size() == 0) return mesh;
    const auto f = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(f_in);
    const size_t m = size_t(f.shape(0));
    const int64_t* q = f.data();
    mesh.faces.resize(m);
    for (size_t i = 0; i < m; ++i)
        for (int k = 0; k < 3; ++k) {
            const int64_t index = q[3 * i + k];
            if (index < 0 || uint64_t(index) >= n)
                fail("F: face " + std::to_string(i) + " refers to vertex " + std::to_string(index) + " but V has " +
                     std::to_string(n) + " vertices");
            mesh.faces[i][k] = uint32_t(index);
        }
    return mesh;
}

void def_io(py::module_& m) {
    py::register_exception<MeshLoadError>(m, "MeshError", PyExc_ValueError);
    m.def(
        "load_mesh",
        [](const py::object& path) {
            const std::string name = path_text(path);
            Mesh mesh;
            {
                py::gil_scoped_release unlocked;
                mesh = load_mesh(name);
            }
            const auto nv = py::ssize_t(mesh.positions.size()), nf = py::ssize_t(mesh.faces.size());
            return py::make_tuple(take_array<glm::vec3, float>(std::move(mesh.positions), {nv, 3}),
                                  take_array<Face, uint32_t>(std::move(mesh.faces), {nf, 3}));
        },
        py::arg("path"),
        R"(Reads a mesh file: .ply .obj .off .stl .gltf .glb (the format from the extension, else the content).

Returns (V, F): V float32 (N, 3) positions, F uint32 (M, 3) triangles (polygons fanned, STL and
glTF vertices welded), as `kappa curvature` reads them. Raises kappa.MeshError (a ValueError) with
the command line's one-line message "PATH: problem".)");
}

}  // namespace kappa::python
