#include "stl_io.h"

#include "byte_order.h"
#include "mesh_assembly.h"
#include "text_cursor.h"
#include "vertex_weld.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

namespace kappa {
namespace io {
namespace {

constexpr size_t kHeaderSize = 84;    // 80-byte comment + uint32 triangle count
constexpr size_t kTriangleSize = 50;  // normal, 3 corners (12 floats), uint16 attribute

uint32_t declared_triangles(const char* data) { return load_little_endian<uint32_t>(data + 80); }

void check_corners_finite(const std::vector<glm::vec3>& corners, const std::string& name) {
    for (size_t i = 0; i < corners.size(); ++i) {
        const glm::vec3& p = corners[i];
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)))
            fail_load(name, "triangle " + std::to_string(i / 3) + " has a non-finite vertex coordinate");
    }
}

Mesh read_binary(const char* data, size_t size, const std::string& name) {
    size_t n = (size - kHeaderSize) / kTriangleSize;
    std::vector<glm::vec3> corners(n * 3);
    const char* p = data + kHeaderSize;
    for (size_t t = 0; t < n; ++t, p += kTriangleSize)
        for (size_t c = 0; c < 3; ++c)
            for (int a = 0; a < 3; ++a)
                corners[3 * t + c][a] = load_little_endian<float>(p + 12 + 12 * c + 4 * a);
    check_corners_finite(corners, name);
    return weld_exact(corners);
}

bool equals_ignoring_case(std::string_view a, const char* b) {
    size_t n = std::strlen(b);
    if (a.size() != n) return false;
    for (size_t i = 0; i < n; ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != b[i]) return false;
    return true;
}

// ASCII: solid NAME / facet normal N / outer loop / vertex X Y Z (x3) /
// endloop / endfacet ... / endsolid NAME; keywords in any case, several
// solids allowed.
Mesh read_ascii(const char* data, size_t size, const std::string& name) {
    TextCursor cursor(data, data + size);
    std::vector<glm::vec3> corners;
    size_t facet_corners = 0, facets = 0;
    bool in_facet = false;
    auto fail_here = [&](const std::string& problem) {
        fail_load(name, problem + " on line " + std::to_string(cursor.line_number()));
    };
    auto number = [&]() {
        std::string_view t = cursor.token();
        float v;
        if (t.empty()) fail_load(name, "unexpected end of file inside facet " + std::to_string(facets));
        if (!parse_number(t, v)) fail_here("bad number " + quoted(t));
        return v;
    };
    for (;;) {
        std::string_view word = cursor.token();
        if (word.empty()) break;
        if (equals_ignoring_case(word, "solid") || equals_ignoring_case(word, "endsolid")) {
            if (in_facet) fail_here("unterminated facet " + std::to_string(facets));
            cursor.skip_line();  // the solid's name
        } else if (equals_ignoring_case(word, "facet")) {
            if (in_facet) fail_here("unterminated facet " + std::to_string(facets));
            in_facet = true;
            facet_corners = 0;
            // "normal nx ny nz": ignored, the corners define the triangle.
            const char* before_normal = cursor.position();
            if (equals_ignoring_case(cursor.token(), "normal")) {
                for (int k = 0; k < 3; ++k) cursor.token();
            } else {
                cursor.set_position(before_normal);
            }
        } else if (equals_ignoring_case(word, "outer") || equals_ignoring_case(word, "loop") ||
                   equals_ignoring_case(word, "endloop")) {
            if (!in_facet) fail_here(quoted(word) + " outside a facet");
        } else if (equals_ignoring_case(word, "vertex")) {
            if (!in_facet) fail_here("vertex outside a facet");
            if (++facet_corners > 3)
                fail_here("facet " + std::to_string(facets) + " has more than 3 vertices");
            float x = number(), y = number(), z = number();
            corners.emplace_back(x, y, z);
        } else if (equals_ignoring_case(word, "endfacet")) {
            if (!in_facet) fail_here("endfacet without facet");
            if (facet_corners != 3)
                fail_here("facet " + std::to_string(facets) + " has " + std::to_string(facet_corners) +
                          " vertices, expected 3");
            in_facet = false;
            ++facets;
        } else {
            fail_here("unexpected " + quoted(word) + " (not an ASCII STL keyword)");
        }
    }
    if (in_facet) fail_load(name, "unexpected end of file inside facet " + std::to_string(facets));
    corners.resize(facets * 3);  // defensive: only complete facets
    check_corners_finite(corners, name);
    return weld_exact(corners);
}

}  // namespace

bool looks_like_binary_stl(const char* data, size_t size) {
    return size >= kHeaderSize &&
           uint64_t(size - kHeaderSize) == uint64_t(declared_triangles(data)) * kTriangleSize;
}

bool looks_like_ascii_stl(const char* data, size_t size) {
    TextCursor cursor(data, data + size);
    if (!equals_ignoring_case(cursor.token(), "solid")) return false;
    // Binary exporters often start their header with "solid" too; a NUL byte
    // early on (float data, count bytes) means binary, whatever the size.
    return std::memchr(data, 0, std::min<size_t>(size, 1024)) == nullptr;
}

}  // namespace io

Mesh read_stl(const char* data, size_t size, const std::string& name) {
    using namespace io;
    Mesh mesh;
    if (looks_like_binary_stl(data, size)) {
        mesh = read_binary(data, size, name);
    } else if (looks_like_ascii_stl(data, size)) {
        mesh = read_ascii(data, size, name);
    } else if (size >= kHeaderSize) {
        uint64_t n = declared_triangles(data);
        fail_load(name, "not a valid STL file: not ASCII STL, and as binary STL its header declares " +
                            std::to_string(n) + " triangles (" +
                            std::to_string(kHeaderSize + n * kTriangleSize) + " bytes) but the file has " +
                            std::to_string(size) + " bytes");
    } else {
        fail_load(name, "not an STL file (too short for binary STL, no 'solid' keyword)");
    }
    if (mesh.faces.empty()) fail_load(name, "the STL file contains no triangles");
    check_loaded_mesh(name, mesh);
    return mesh;
}

}  // namespace kappa
