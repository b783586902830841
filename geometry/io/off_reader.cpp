#include "off_io.h"

#include "mesh_assembly.h"
#include "text_cursor.h"

#include <limits>
#include <vector>

namespace kappa {
namespace io {
namespace {

// Tokens of an OFF file: whitespace-separated, '#' starts a comment that runs
// to the end of the line.
class OffTokens {
public:
    OffTokens(const char* begin, const char* end, const std::string& name)
        : cursor_(begin, end), name_(&name) {}

    // The next token; with in_line, only if it is on the current line.
    std::string_view next(bool in_line = false) {
        if (in_line) {
            cursor_.skip_blank();
            if (cursor_.at_line_end('#')) return {};
            return cursor_.token_in_line();
        }
        for (;;) {
            cursor_.skip_space();
            if (!cursor_.at_end() && *cursor_.position() == '#') {
                cursor_.skip_line();
                continue;
            }
            return cursor_.token();
        }
    }

    // Skips the rest of the current line (extra values, colours, comments).
    void end_line() { cursor_.skip_line(); }

    template <typename T>
    T number(const char* what, bool in_line = false) {
        std::string_view t = next(in_line);
        if (t.empty() && in_line && !cursor_.at_end())
            fail_load(*name_, std::string("line ") + std::to_string(cursor_.line_number()) +
                                  " ends too early while reading " + what);
        if (t.empty())
            fail_load(*name_, std::string("unexpected end of file while reading ") + what +
                                  " (the file is truncated or its counts are wrong)");
        T value;
        if (!parse_number(t, value))
            fail_load(*name_, "bad number " + quoted(t) + " on line " +
                                  std::to_string(cursor_.line_number()) + " while reading " + what);
        return value;
    }

    size_t remaining() const { return cursor_.remaining(); }
    bool at_line_end() {
        cursor_.skip_blank();
        return cursor_.at_line_end('#');
    }

private:
    TextCursor cursor_;
    const std::string* name_;
};

// Splits "[ST][C][N][4][n]OFF" into its prefixes; false if not an OFF keyword.
struct OffKeyword {
    bool four_d = false, n_dim = false, binary = false;
};
bool parse_keyword(std::string_view word, OffKeyword& kw) {
    auto eat = [&](std::string_view prefix) {
        if (word.substr(0, prefix.size()) != prefix) return false;
        word.remove_prefix(prefix.size());
        return true;
    };
    eat("ST");
    eat("C");
    eat("N");
    kw.four_d = eat("4");
    kw.n_dim = eat("n");
    return word == "OFF";
}

}  // namespace

bool looks_like_off(const char* data, size_t size) {
    TextCursor cursor(data, data + size);
    for (;;) {
        cursor.skip_space();
        if (cursor.at_end() || *cursor.position() != '#') break;
        cursor.skip_line();
    }
    std::string_view word = cursor.token();
    // "OFF8" style keywords glued to counts are not valid OFF.
    OffKeyword kw;
    return parse_keyword(word, kw);
}

}  // namespace io

Mesh read_off(const char* data, size_t size, const std::string& name) {
    using namespace io;
    if (size == 0) fail_load(name, "file is empty");
    OffTokens tokens(data, data + size, name);

    // Header keyword (optional in practice: some writers start with the counts).
    OffTokens probe = tokens;
    std::string_view first = probe.next();
    OffKeyword kw;
    if (first.empty()) fail_load(name, "file contains only comments and blank lines");
    if (parse_keyword(first, kw)) {
        tokens = probe;
        std::string_view rest = tokens.next();
        if (rest == "BINARY") fail_load(name, "binary OFF files are not supported");
        tokens = probe;  // counts may follow on the same line
    } else if (!(first[0] >= '0' && first[0] <= '9')) {
        fail_load(name, "not an OFF file (expected the keyword OFF, found " + quoted(first) + ")");
    }
    // The dimension: 3, or nOFF's as written; 4 adds a homogeneous coordinate
    // (compared as written: the largest uint64 plus one would wrap to 0).
    const uint64_t dimension = kw.n_dim ? tokens.number<uint64_t>("the dimension of nOFF") : 3;
    if (dimension != (kw.four_d ? 2 : 3))
        fail_load(name, "only 3-D OFF files are supported (this one has dimension " + std::to_string(dimension) +
                            (kw.four_d ? " + 1)" : ")"));

    uint64_t nv = tokens.number<uint64_t>("the vertex count");
    uint64_t nf = tokens.number<uint64_t>("the face count");
    if (!tokens.at_line_end()) tokens.number<uint64_t>("the edge count");  // unused
    tokens.end_line();
    // Each vertex line needs at least 6 bytes ("0 0 0\n"), each face 2 ("0\n"):
    // reject impossible counts before allocating anything.
    uint64_t left = tokens.remaining() + 1;
    if (nv > left / 6 || nf > (left - nv * 6) / 2)
        fail_load(name, "header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                            " faces but the file has only " + std::to_string(size) +
                            " bytes (truncated or corrupt)");
    // Faces hold 32-bit vertex numbers, as in PLY (only files over 24 GiB get here).
    if (nv > std::numeric_limits<uint32_t>::max())
        fail_load(name, "too many vertices (" + std::to_string(nv) + ")");

    Mesh mesh;
    mesh.positions.resize(size_t(nv));
    for (size_t i = 0; i < nv; ++i) {
        glm::vec3& p = mesh.positions[i];
        p.x = tokens.number<float>("vertex coordinates");
        p.y = tokens.number<float>("vertex coordinates", true);
        p.z = tokens.number<float>("vertex coordinates", true);
        tokens.end_line();  // normals, colours, texture coordinates
    }
    mesh.faces.reserve(size_t(nf));
    std::vector<int64_t> polygon;
    for (uint64_t f = 0; f < nf; ++f) {
        uint64_t n = tokens.number<uint64_t>("a face");
        if (n > tokens.remaining() / 2 + 1)
            fail_load(name, "face " + std::to_string(f) + " claims " + std::to_string(n) +
                                " vertices, more than the file can hold");
        polygon.resize(size_t(n));
        for (auto& index : polygon) index = tokens.number<int64_t>("a face");
        tokens.end_line();  // optional face colour
        add_polygon(name, "face", f, polygon.data(), polygon.size(), size_t(nv), mesh.faces);
    }
    check_loaded_mesh(name, mesh);
    return mesh;
}

}  // namespace kappa
