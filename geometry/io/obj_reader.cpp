// tinyobjloader parses the faces (all corner syntaxes, relative indices).
// Three of its behaviours are worked around:
// - it only sees the `v` and `f` statements (the others are blanked, keeping
//   line numbers): nothing else is used, and some of its other parsers have
//   undefined behaviour on hostile input (fuzzing found a float-to-int
//   overflow in its `vw` skin-weight extension);
// - its triangulation splits quads along the shorter diagonal, ear-clips
//   larger polygons and silently drops faces with invalid indices, so faces
//   are loaded untriangulated and fan-triangulated here (as in every other
//   format), with every index checked;
// - it reads an unparsable coordinate ("nan", "inf", "abc", a missing z) as
//   0 without a warning, so the `v` lines are also read here, with the same
//   line splitting, and every coordinate must be a finite number.
#include "obj_io.h"

#include "mesh_assembly.h"
#include "text_cursor.h"

#include <tiny_obj_loader.h>

#include <cmath>
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

// Calls on_line(line_number, statement, line) for each line, split as
// tinyobjloader's safeGetline does ("\n", "\r\n" or "\r"); statement is
// 'v' or 'f' for those statements (keyword then a space or tab), else 0.
template <typename OnLine>
void for_each_line(const char* data, size_t size, OnLine&& on_line) {
    size_t line_number = 0, pos = 0;
    while (pos < size) {
        size_t end = pos;
        while (end < size && data[end] != '\n' && data[end] != '\r') ++end;
        ++line_number;
        size_t p = pos;
        while (p < end && (data[p] == ' ' || data[p] == '\t')) ++p;
        char statement = 0;
        if (end - p >= 2 && (data[p] == 'v' || data[p] == 'f') && (data[p + 1] == ' ' || data[p + 1] == '\t'))
            statement = data[p];
        on_line(line_number, statement, std::string_view(data + p, end - p));
        pos = end + 1;
        if (end < size && data[end] == '\r' && pos < size && data[pos] == '\n') ++pos;
    }
}

// The `v` and `f` lines of the file, other lines left empty.
std::string vertex_and_face_lines(const char* data, size_t size) {
    std::string out;
    out.reserve(size);
    for_each_line(data, size, [&](size_t, char statement, std::string_view line) {
        if (statement) out += line;
        out += '\n';
    });
    return out;
}

// The positions of all `v` statements, in order; x y z must be finite
// numbers (a fourth w or r g b colour values may follow and are ignored).
std::vector<glm::vec3> read_positions(const char* data, size_t size, const std::string& name) {
    std::vector<glm::vec3> positions;
    for_each_line(data, size, [&](size_t line, char statement, std::string_view text) {
        if (statement != 'v') return;
        TextCursor cursor(text.data() + 2, text.data() + text.size());
        glm::vec3 p;
        for (int a = 0; a < 3; ++a) {
            std::string_view token = cursor.token();
            if (token.empty() || !parse_number(token, p[a]) || !std::isfinite(p[a]))
                fail_load(name, "line " + std::to_string(line) + ": vertex " +
                                    std::to_string(positions.size()) +
                                    (token.empty() ? std::string(" has fewer than 3 coordinates")
                                                   : " has a bad coordinate " + quoted(token)));
        }
        positions.push_back(p);
    });
    return positions;
}

std::string first_line(const std::string& text) {
    size_t end = text.find('\n');
    std::string line = text.substr(0, end);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '.'))
        line.pop_back();
    return line;
}

}  // namespace
}  // namespace io

Mesh read_obj(const char* data, size_t size, const std::string& name) {
    using namespace io;
    if (size == 0) fail_load(name, "file is empty");
    const std::string statements = vertex_and_face_lines(data, size);
    MemoryBuffer buffer(statements.data(), statements.size());
    std::istream stream(&buffer);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, errors;
    bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &stream,
                               /*readMatFn=*/nullptr, /*triangulate=*/false);
    if (!ok) fail_load(name, "OBJ parse error: " + first_line(errors.empty() ? "unknown error" : errors));

    Mesh mesh;
    mesh.positions = read_positions(data, size, name);
    const size_t vertex_count = mesh.positions.size();
    if (attrib.vertices.size() != 3 * vertex_count)
        fail_load(name, "OBJ parser found " + std::to_string(attrib.vertices.size() / 3) +
                            " vertices, expected " + std::to_string(vertex_count));

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
