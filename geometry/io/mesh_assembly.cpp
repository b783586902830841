#include "mesh_assembly.h"

#include "io_errors.h"

#include <cmath>
#include <sstream>

namespace kappa::io {

void fail_bad_index(const std::string& name, const char* what, uint64_t number, int64_t index,
                    size_t vertex_count) {
    fail_load(name, std::string(what) + " " + std::to_string(number) + " refers to vertex " +
                        std::to_string(index) + " but the file has " + std::to_string(vertex_count) +
                        " vertices");
}

void add_polygon(const std::string& name, const char* what, uint64_t number, const int64_t* indices,
                 size_t count, size_t vertex_count, std::vector<Face>& faces) {
    for (size_t i = 0; i < count; ++i)
        if (!valid_index(indices[i], vertex_count))
            fail_bad_index(name, what, number, indices[i], vertex_count);
    for (size_t i = 1; i + 1 < count; ++i)
        faces.emplace_back(uint32_t(indices[0]), uint32_t(indices[i]), uint32_t(indices[i + 1]));
}

void add_triangle_strips(const std::string& name, uint64_t number, const int64_t* indices, size_t count,
                         int64_t restart, size_t vertex_count, std::vector<Face>& faces) {
    size_t strip_start = 0;
    for (size_t i = 0; i < count; ++i) {
        int64_t v = indices[i];
        if (v == -1 || v == restart) {
            strip_start = i + 1;
            continue;
        }
        if (!valid_index(v, vertex_count)) fail_bad_index(name, "triangle strip", number, v, vertex_count);
        size_t k = i - strip_start;  // position of v within its strip
        if (k < 2) continue;
        uint32_t a = uint32_t(indices[i - 2]), b = uint32_t(indices[i - 1]), c = uint32_t(v);
        if (a == b || b == c || a == c) continue;  // degenerate stitching triangle
        if (k % 2 == 0)
            faces.emplace_back(a, b, c);
        else
            faces.emplace_back(b, a, c);
    }
}

void check_loaded_mesh(const std::string& name, const Mesh& mesh) {
    if (mesh.positions.empty()) fail_load(name, "the file contains no vertices");
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3& p = mesh.positions[i];
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) continue;
        std::ostringstream msg;
        msg << "vertex " << i << " has a non-finite coordinate (" << p.x << ", " << p.y << ", " << p.z << ")";
        fail_load(name, msg.str());
    }
}

}  // namespace kappa::io
