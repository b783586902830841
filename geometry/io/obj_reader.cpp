// tinyobjloader's own triangulation is not used: it splits quads along the
// shorter diagonal and ear-clips larger polygons, silently dropping faces with
// invalid indices. Loading untriangulated and fan-triangulating here keeps
// the result identical to the other formats and lets every index be checked.
#include "obj_io.h"

#include "mesh_assembly.h"

#include <tiny_obj_loader.h>

#include <istream>
#include <streambuf>

namespace kappa {
namespace io {
namespace {

// A read-only std::streambuf over memory, so tinyobjloader parses in place.
class MemoryBuffer : public std::streambuf {
public:
    MemoryBuffer(const char* data, size_t size) {
        char* p = const_cast<char*>(data);  // never written through: get area only
        setg(p, p, p + size);
    }
};

std::string first_line(const std::string& text) {
    size_t end = text.find('\n');
    std::string line = text.substr(0, end);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '.')) line.pop_back();
    return line;
}

}  // namespace
}  // namespace io

Mesh read_obj(const char* data, size_t size, const std::string& name) {
    using namespace io;
    if (size == 0) fail_load(name, "file is empty");
    MemoryBuffer buffer(data, size);
    std::istream stream(&buffer);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, errors;
    bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &stream,
                               /*readMatFn=*/nullptr, /*triangulate=*/false);
    if (!ok) fail_load(name, "OBJ parse error: " + first_line(errors.empty() ? "unknown error" : errors));

    Mesh mesh;
    const size_t vertex_count = attrib.vertices.size() / 3;
    mesh.positions.resize(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i)
        mesh.positions[i] = {attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]};

    std::vector<int64_t> polygon;
    uint64_t face_number = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        const auto& corners = shape.mesh.indices;
        // tinyobjloader stores corner counts in a byte: a polygon with more
        // than 255 corners shows up as counts that do not add up.
        size_t total = 0;
        for (unsigned int n : shape.mesh.num_face_vertices) total += n;
        if (total != corners.size())
            fail_load(name, "a face has more than 255 corners (not supported by the OBJ reader)");
        size_t next = 0;
        for (unsigned int n : shape.mesh.num_face_vertices) {
            polygon.resize(n);
            for (size_t k = 0; k < n; ++k) polygon[k] = corners[next + k].vertex_index;
            next += n;
            add_polygon(name, "face", face_number++, polygon.data(), n, vertex_count, mesh.faces);
        }
    }
    check_loaded_mesh(name, mesh);
    return mesh;
}

}  // namespace kappa
