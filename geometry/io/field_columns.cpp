#include "field_columns.h"

#include "io_errors.h"

namespace kappa::io {

const char* const kFieldColumnNames[kFieldColumnCount] = {"x",   "y",   "z",   "nx",  "ny",  "nz",
                                                          "k1",  "k2",  "d1x", "d1y", "d1z", "d2x",
                                                          "d2y", "d2z", "a",   "b",   "c",   "d"};

void check_fields_match(const std::string& path, const Mesh& mesh, const SurfaceFields& f) {
    const size_t n = mesh.vertex_count();
    auto check = [&](size_t size, const char* field) {
        if (size != n)
            fail_write(path, std::string("surface field '") + field + "' has " + std::to_string(size) +
                                 " entries but the mesh has " + std::to_string(n) + " vertices");
    };
    check(f.normals.size(), "normals");
    check(f.k1.size(), "k1");
    check(f.k2.size(), "k2");
    check(f.d1.size(), "d1");
    check(f.d2.size(), "d2");
    check(f.dcurv.size(), "dcurv");
    if (!f.flags.empty()) check(f.flags.size(), "flags");
}

}  // namespace kappa::io
