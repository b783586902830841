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
//   line splitting, and every coordinate must be a finite number;
// - it reads vertex indices with atoi into an int, so an index beyond 32
//   bits wraps round (99999999999 to 1215752191, 4294967298 to 2, a valid
//   vertex): the vertex index of every corner is checked here first, as
//   written, in 64 bits (read_positions), and errors quote it.
#include "obj_io.h"

#include "mesh_assembly.h"
#include "text_cursor.h"

#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <istream>
#include <streambuf>
#include <utility>

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

// The vertex index of one corner of an `f` statement ("v", "v/vt", "v//vn",
// "v/vt/vn") as atoi reads it: a sign, then digits.
struct WrittenIndex {
    std::string_view text;  // as written: the sign and the digits
    bool negative = false;
    bool fits = false;       // the digits fit in 64 bits (magnitude)
    uint64_t magnitude = 0;
};

// Reads the corner at p (not a blank) up to the next blank or `end`; false
// if it does not start with a number (atoi then reads 0: tinyobjloader's
// error). One pass over the characters: this runs for every corner.
bool read_corner(const char*& p, const char* end, WrittenIndex& out) {
    while (p < end && (*p == '\v' || *p == '\f')) ++p;  // atoi skips these too
    const char* start = p;
    out.negative = p < end && *p == '-';
    if (p < end && (*p == '-' || *p == '+')) ++p;
    const char* digits = p;
    uint64_t m = 0;
    while (p < end && unsigned(*p - '0') < 10) m = m * 10 + unsigned(*p++ - '0');
    const char* digits_end = p;
    while (p < end && *p != ' ' && *p != '\t') ++p;  // "/vt/vn"
    if (digits_end == digits) return false;
    out.text = std::string_view(start, size_t(digits_end - start));
    out.magnitude = m;
    out.fits = digits_end - digits < 20 ||  // up to 19 digits cannot overflow; more may (or be zeros)
               std::from_chars(digits, digits_end, out.magnitude).ec == std::errc();
    return true;
}

// A corner's vertex index that is out of range, or that tinyobjloader's int
// cannot hold; reported once the file's vertex count is known.
struct BadIndex {
    size_t line = 0;
    uint64_t face = 0;
    WrittenIndex index;
    size_t vertices_before = 0;  // `v` statements before the face (for relative indices)
};

[[noreturn]] void fail_bad_corner(const std::string& name, const BadIndex& bad, size_t vertex_count) {
    const WrittenIndex& w = bad.index;
    const std::string where = "line " + std::to_string(bad.line) + ": face " + std::to_string(bad.face);
    const std::string written = std::string(w.text);
    const bool resolvable = w.fits && w.magnitude <= uint64_t(INT64_MAX);
    if (!resolvable)
        fail_load(name, where + " has vertex index " + written + ", out of range (the file has " +
                            std::to_string(vertex_count) + " vertices)");
    // The 0-based vertex it names, as in the other readers' messages.
    const int64_t vertex =
        w.negative ? int64_t(bad.vertices_before) - int64_t(w.magnitude) : int64_t(w.magnitude) - 1;
    if (vertex >= 0 && uint64_t(vertex) < vertex_count)  // only with 2^31 vertices or more
        fail_load(name, where + ": vertex index " + written + " is beyond the 32-bit indices of the OBJ reader");
    fail_load(name, where + " refers to vertex " + std::to_string(vertex) + " but the file has " +
                        std::to_string(vertex_count) + " vertices (index " + written + " as written)");
}

// The positions of all `v` statements, in order; x y z must be finite
// numbers (a fourth w or r g b colour values may follow and are ignored).
// The vertex index of every corner of the `f` statements is checked too:
// it must name one of the vertices (relative ones: of those before it) and
// fit in tinyobjloader's int; the first one that does not, in file order, is
// the error. Faces are numbered as read_obj numbers them (faces with fewer
// than 3 corners, which tinyobjloader drops, are not counted).
std::vector<glm::vec3> read_positions(const char* data, size_t size, const std::string& name) {
    std::vector<glm::vec3> positions;
    // Positive indices beyond the vertices so far (legal: OBJ allows forward
    // references) can only be judged at the end. Kept: each one larger than
    // all before it, in file order; the first of those beyond the vertex
    // count is the first bad one.
    std::vector<BadIndex> forward;
    BadIndex first_bad;  // the first index bad whatever follows (line 0: none)
    uint64_t face = 0;
    for_each_line(data, size, [&](size_t line, char statement, std::string_view text) {
        if (statement == 'f') {
            if (first_bad.line != 0) return;  // only the vertex count is still needed
            const char* p = text.data() + 2;
            const char* end = text.data() + text.size();
            size_t corners = 0;
            for (;;) {
                while (p < end && (*p == ' ' || *p == '\t')) ++p;  // lines end before any '\r'
                if (p == end) break;
                ++corners;
                WrittenIndex w;
                if (!read_corner(p, end, w)) continue;
                bool ok = true;
                if (!w.fits) {
                    ok = false;
                } else if (w.negative) {  // relative: -1 is the last vertex so far
                    ok = w.magnitude <= positions.size() && w.magnitude <= 2147483648u;
                } else if (w.magnitude > 2147483647u) {
                    ok = false;
                } else if (w.magnitude > positions.size() &&
                           (forward.empty() || w.magnitude > forward.back().index.magnitude)) {
                    forward.push_back({line, face, w, positions.size()});
                }
                if (!ok) {
                    first_bad = {line, face, w, positions.size()};
                    return;
                }
            }
            face += corners >= 3;
            return;
        }
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
    for (const BadIndex& f : forward)
        if (f.index.magnitude > positions.size() && (first_bad.line == 0 || f.line <= first_bad.line))
            fail_bad_corner(name, f, positions.size());
    if (first_bad.line != 0) fail_bad_corner(name, first_bad, positions.size());
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
    // Positions and vertex indices first: tinyobjloader would wrap indices.
    std::vector<glm::vec3> positions = read_positions(data, size, name);
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
    mesh.positions = std::move(positions);
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
