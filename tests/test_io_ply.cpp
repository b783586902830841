// Handcrafted PLY files: every encoding, every property type and alias,
// extra and list properties, unknown elements, polygons and triangle strips.
#include "geometry/parallel/parallel.h"
#include "test_io_support.h"

#include <cstdio>

using namespace kappa;
using kappa::test::Bytes;
using kappa::test::ply_from;

namespace {

enum class Encoding { Ascii, Little, Big };

const char* format_name(Encoding e) {
    return e == Encoding::Ascii    ? "ascii"
           : e == Encoding::Little ? "binary_little_endian"
                                   : "binary_big_endian";
}

// Writes values in one encoding; ASCII values are separated by spaces and
// items end with a newline.
class Body {
public:
    explicit Body(Encoding e) : enc_(e) {}
    template <typename T>
    Body& operator()(T value) {
        if (enc_ == Encoding::Ascii) {
            char buf[64];
            if constexpr (std::is_floating_point_v<T>)
                std::snprintf(buf, sizeof buf, "%.17g ", double(value));
            else
                std::snprintf(buf, sizeof buf, "%lld ", (long long)value);
            bytes_.text(buf);
        } else if (enc_ == Encoding::Little) {
            bytes_.le(value);
        } else {
            bytes_.be(value);
        }
        return *this;
    }
    Body& end_item() {
        if (enc_ == Encoding::Ascii) bytes_.text("\n");
        return *this;
    }
    const std::string& str() const { return bytes_.str(); }

private:
    Encoding enc_;
    Bytes bytes_;
};

std::string header(Encoding e, const std::string& elements) {
    return std::string("ply\nformat ") + format_name(e) + " 1.0\n" + elements + "end_header\n";
}

const glm::vec3 kSquare[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

}  // namespace

TEST_CASE("PLY: minimal ascii quad is fan-triangulated", "[io][ply]") {
    Mesh m = ply_from(
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    REQUIRE(m.vertex_count() == 4);
    for (int i = 0; i < 4; ++i) CHECK(m.positions[i] == kSquare[i]);
    REQUIRE(m.face_count() == 2);
    CHECK(m.faces[0] == Face(0, 1, 2));
    CHECK(m.faces[1] == Face(0, 2, 3));
}

TEST_CASE("PLY: comments, obj_info, CRLF line endings, blank lines, vertex_index", "[io][ply]") {
    std::string text =
        "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info anything at all\r\n\r\n"
        "element vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
        "comment between properties\r\nelement face 1\r\nproperty list uchar uint vertex_index\r\n"
        "end_header\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
    Mesh m = ply_from(text);
    CHECK(m.vertex_count() == 3);
    REQUIRE(m.face_count() == 1);
    CHECK(m.faces[0] == Face(0, 1, 2));
    CHECK(m.positions[1] == glm::vec3(1, 0, 0));
}

TEST_CASE("PLY: every property type and alias, extra lists, unknown elements, in every encoding",
          "[io][ply]") {
    Encoding enc = GENERATE(Encoding::Ascii, Encoding::Little, Encoding::Big);
    INFO(format_name(enc));
    // x, y, z of three different float types among scalars of every type and
    // two list properties; faces with extra scalars and lists around the
    // indices; an unknown element with a list before and after the faces.
    std::string elements =
        "element vertex 4\n"
        "property char a\nproperty uchar b\nproperty short c\nproperty ushort d\nproperty int e\n"
        "property uint f\nproperty float x\nproperty list uchar float normals_list\nproperty double g\n"
        "property int8 h\nproperty uint8 i\nproperty int16 j\nproperty uint16 k\nproperty float32 y\n"
        "property int32 l\nproperty uint32 m\nproperty list int16 int32 more\nproperty float64 z\n"
        "property float64 n\n"
        "element edge 2\nproperty list uint16 uint vertices\nproperty uchar red\n"
        "element face 2\nproperty uint8 tag\nproperty list ushort short vertex_indices\n"
        "property list uint float texcoord\nproperty double weight\n"
        "element material 1\nproperty list char double values\nproperty float shine\n";
    Body body(enc);
    const double z_values[4] = {0.1, -2.5e-3, 1e10, 0.0};
    for (int v = 0; v < 4; ++v) {
        body(int8_t(-7))(uint8_t(200))(int16_t(-30000))(uint16_t(60000))(int32_t(-2000000000))(
            uint32_t(4000000000u));
        body(float(kSquare[v].x));
        body(uint8_t(3))(1.5f)(2.5f)(3.5f);  // normals_list
        body(1e300)(int8_t(-1))(uint8_t(1))(int16_t(-1))(uint16_t(1));
        body(float(kSquare[v].y));
        body(int32_t(-1))(uint32_t(1));
        body(int16_t(2))(int32_t(7))(int32_t(8));  // more
        body(z_values[v])(-1e-300);
        body.end_item();
    }
    for (int e = 0; e < 2; ++e) body(uint16_t(2))(uint32_t(0))(uint32_t(1))(uint8_t(255)).end_item();
    // face 0: quad; face 1: triangle
    body(uint8_t(9))(uint16_t(4))(int16_t(0))(int16_t(1))(int16_t(2))(int16_t(3));
    body(uint32_t(2))(0.25f)(0.75f)(0.5).end_item();
    body(uint8_t(9))(uint16_t(3))(int16_t(3))(int16_t(2))(int16_t(1));
    body(uint32_t(0))(-0.5).end_item();
    body(int8_t(2))(1.0)(2.0)(0.5f).end_item();

    std::string file = header(enc, elements) + body.str();
    Mesh m = ply_from(file);
    REQUIRE(m.vertex_count() == 4);
    for (int v = 0; v < 4; ++v) {
        CHECK(m.positions[v].x == kSquare[v].x);
        CHECK(m.positions[v].y == kSquare[v].y);
        CHECK(m.positions[v].z == float(z_values[v]));
    }
    REQUIRE(m.face_count() == 3);
    CHECK(m.faces[0] == Face(0, 1, 2));
    CHECK(m.faces[1] == Face(0, 2, 3));
    CHECK(m.faces[2] == Face(3, 2, 1));
}

TEST_CASE("PLY: big-endian float vertices and uchar/int faces", "[io][ply]") {
    Bytes b;
    b.text(header(Encoding::Big,
                  "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 1\nproperty list uchar int vertex_indices\n"));
    b.be(1.25f).be(-2.0f).be(3.0e-5f).be(4.0f).be(5.0f).be(6.0f).be(7.0f).be(8.0f).be(9.0f);
    b.be(uint8_t(3)).be(int32_t(2)).be(int32_t(1)).be(int32_t(0));
    Mesh m = ply_from(b.str());
    REQUIRE(m.vertex_count() == 3);
    CHECK(m.positions[0] == glm::vec3(1.25f, -2.0f, 3.0e-5f));
    CHECK(m.positions[2] == glm::vec3(7, 8, 9));
    REQUIRE(m.face_count() == 1);
    CHECK(m.faces[0] == Face(2, 1, 0));
}

TEST_CASE("PLY: double coordinates (binary and ascii)", "[io][ply]") {
    Encoding enc = GENERATE(Encoding::Ascii, Encoding::Little, Encoding::Big);
    Body body(enc);
    body(0.1)(0.2)(0.3).end_item()(1e-3)(-123456.789)(2.0).end_item()(0.0)(1.0)(-1.0).end_item();
    body(uint8_t(3))(int32_t(0))(int32_t(1))(int32_t(2)).end_item();
    Mesh m = ply_from(header(enc,
                             "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                             "element face 1\nproperty list uchar int vertex_indices\n") +
                      body.str());
    CHECK(m.positions[0] == glm::vec3(float(0.1), float(0.2), float(0.3)));
    CHECK(m.positions[1] == glm::vec3(float(1e-3), float(-123456.789), 2.0f));
    CHECK(m.face_count() == 1);
}

TEST_CASE("PLY: fast-path layout with extra fixed-size properties", "[io][ply]") {
    // vertex: x y z + float confidence (like bunny-1M); face: int flags
    // before and after the index list (fast face path with prefix/suffix).
    Bytes b;
    b.text(header(Encoding::Little,
                  "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                  "property float confidence\nelement face 3\nproperty int before\n"
                  "property list uchar int vertex_indices\nproperty uint after\n"));
    for (const glm::vec3& p : kSquare) b.le(p.x).le(p.y).le(p.z).le(0.5f);
    b.le(int32_t(-1)).le(uint8_t(3)).le(int32_t(0)).le(int32_t(1)).le(int32_t(2)).le(uint32_t(7));
    b.le(int32_t(-1))
        .le(uint8_t(4))
        .le(int32_t(0))
        .le(int32_t(1))
        .le(int32_t(2))
        .le(int32_t(3))
        .le(uint32_t(7));
    b.le(int32_t(-1)).le(uint8_t(2)).le(int32_t(0)).le(int32_t(1)).le(uint32_t(7));  // an edge: no triangle
    Mesh m = ply_from(b.str());
    REQUIRE(m.vertex_count() == 4);
    for (int i = 0; i < 4; ++i) CHECK(m.positions[i] == kSquare[i]);
    REQUIRE(m.face_count() == 3);
    CHECK(m.faces[0] == Face(0, 1, 2));
    CHECK(m.faces[1] == Face(0, 1, 2));
    CHECK(m.faces[2] == Face(0, 2, 3));
}

TEST_CASE("PLY: polygons of any size are fan-triangulated", "[io][ply]") {
    Mesh m = ply_from(
        "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 3\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 2 0\n-1 1 0\n"
        "6 0 1 2 3 4 5\n2 0 1\n0\n");
    REQUIRE(m.face_count() == 4);
    for (int k = 0; k < 4; ++k) CHECK(m.faces[k] == Face(0, k + 1, k + 2));
}

TEST_CASE("PLY: tristrips with restarts, alternating winding and stitching triangles", "[io][ply]") {
    Encoding enc = GENERATE(Encoding::Ascii, Encoding::Little, Encoding::Big);
    auto load_strips = [&](const std::vector<int32_t>& strips) {
        Body body(enc);
        for (int i = 0; i < 8; ++i) body(float(i))(float(i % 2))(0.0f).end_item();
        body(int32_t(strips.size()));
        for (int32_t v : strips) body(v);
        body.end_item();
        return ply_from(header(enc,
                               "element vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
                               "element tristrips 1\nproperty list int int vertex_indices\n") +
                        body.str());
    };
    // Triangle k of a strip is (s[k], s[k+1], s[k+2]), first two swapped for
    // odd k, so that every triangle has the orientation of the first.
    const std::vector<Face> expected = {{0, 1, 2}, {2, 1, 3}, {4, 5, 6}, {6, 5, 7}};
    SECTION("-1 restarts a strip") { CHECK(load_strips({0, 1, 2, 3, -1, 4, 5, 6, 7}).faces == expected); }
    SECTION("strips stitched by repeated indices give the same triangles") {
        CHECK(load_strips({0, 1, 2, 3, 3, 4, 4, 5, 6, 7}).faces == expected);
    }
}

TEST_CASE("PLY: unsigned strip indices restart at their all-ones value", "[io][ply]") {
    Bytes b;
    b.text(header(Encoding::Little,
                  "element vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
                  "element tristrips 1\nproperty list uchar uint vertex_indices\n"));
    for (int i = 0; i < 6; ++i) b.le(float(i)).le(float(i % 2)).le(0.0f);
    b.le(uint8_t(7)).le(0u).le(1u).le(2u).le(0xffffffffu).le(3u).le(4u).le(5u);
    Mesh m = ply_from(b.str());
    CHECK(m.faces == std::vector<Face>{{0, 1, 2}, {3, 4, 5}});
}

TEST_CASE("PLY: element order, no faces, and several face elements", "[io][ply]") {
    SECTION("faces before vertices") {
        Mesh m = ply_from(
            "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
            "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
            "3 2 1 0\n0 0 0\n1 0 0\n0 1 0\n");
        CHECK(m.vertex_count() == 3);
        CHECK(m.faces == std::vector<Face>{{2, 1, 0}});
    }
    SECTION("a point cloud: vertices only") {
        Mesh m = ply_from(
            "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
            "end_header\n1 2 3\n4 5 6\n");
        CHECK(m.vertex_count() == 2);
        CHECK(m.face_count() == 0);
    }
    SECTION("an empty face element") {
        Mesh m = ply_from(
            "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n" +
            Bytes().le(1.0f).le(2.0f).le(3.0f).str());
        CHECK(m.vertex_count() == 1);
        CHECK(m.positions[0] == glm::vec3(1, 2, 3));
        CHECK(m.face_count() == 0);
    }
    SECTION("elements with no properties are skipped whatever their count") {
        Mesh m = ply_from(
            "ply\nformat binary_little_endian 1.0\nelement nothing 999999999999\nelement vertex 1\n"
            "property float x\nproperty float y\nproperty float z\nend_header\n" +
            Bytes().le(1.0f).le(2.0f).le(3.0f).str());
        CHECK(m.vertex_count() == 1);
    }
}

TEST_CASE("PLY: many triangles read by all threads, and what makes the reader fall back", "[io][ply]") {
    // 70,000 faces (the parallel path takes 65,536 or more, io/ply_reader.cpp)
    // with an int before and a float after the list; then the same with one
    // quad, one bad index and one truncated record, which the serial loop
    // must handle exactly as for a short file.
    const int n = 70000;
    auto file = [&](int quad_at, int bad_at, bool truncated) {
        Bytes b;
        b.text(header(Encoding::Little, "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                                        "element face " + std::to_string(n) + "\nproperty int id\n"
                                        "property list uchar int vertex_indices\nproperty float w\n"));
        for (const glm::vec3& p : kSquare) b.le(p.x).le(p.y).le(p.z);
        for (int i = 0; i < n; ++i) {
            b.le(int32_t(i));
            if (i == quad_at)
                b.le(uint8_t(4)).le(int32_t(0)).le(int32_t(1)).le(int32_t(2)).le(int32_t(3));
            else
                b.le(uint8_t(3)).le(int32_t(i % 4)).le(int32_t(i == bad_at ? 9 : (i + 1) % 4)).le(int32_t((i + 2) % 4));
            b.le(0.5f);
        }
        std::string bytes = b.str();
        if (truncated) bytes.resize(bytes.size() - 3);
        return bytes;
    };
    for (unsigned threads : {1u, 2u, 3u}) {
        set_thread_count(threads);
        CAPTURE(threads);
        const Mesh all = ply_from(file(-1, -1, false));
        REQUIRE(all.face_count() == size_t(n));
        size_t wrong = 0;
        for (int i = 0; i < n; ++i) wrong += all.faces[size_t(i)] != Face(i % 4, (i + 1) % 4, (i + 2) % 4);
        CHECK(wrong == 0);

        const Mesh with_quad = ply_from(file(40000, -1, false));  // the quad: two triangles
        REQUIRE(with_quad.face_count() == size_t(n + 1));
        CHECK(with_quad.faces[40000] == Face(0, 1, 2));
        CHECK(with_quad.faces[40001] == Face(0, 2, 3));
        CHECK(with_quad.faces[40002] == Face(40001 % 4, 40002 % 4, 40003 % 4));

        CHECK_THROWS_WITH(ply_from(file(-1, 50000, false)),
                          Catch::Contains("face 50000 refers to vertex 9 but the file has 4 vertices"));
        CHECK_THROWS_WITH(ply_from(file(-1, -1, true)), Catch::Contains("unexpected end of file"));
    }
    set_thread_count(0);
}

TEST_CASE("PLY: indices and counts beyond their types or the vertices are errors quoting them as written",
          "[io][ply]") {
    const std::string xyz = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    // Three vertices, then one face element of the given list type whose
    // single item is the count and indices given (in the file's encoding).
    auto file = [&](Encoding e, const std::string& list_types, auto count, auto... indices) {
        Body body(e);
        for (int i = 0; i < 9; ++i) body(float(i == 3 || i == 7));
        body.end_item()(count);
        (body(indices), ...);
        body.end_item();
        return header(e, xyz + "element face 1\nproperty list " + list_types + " vertex_indices\n") + body.str();
    };
    const std::string beyond = " but the file has 3 vertices";
    for (Encoding e : {Encoding::Ascii, Encoding::Little, Encoding::Big}) {
        INFO(format_name(e));
        // uint32 indices past INT_MAX and past the vertex count: the
        // little-endian ones take the fast path (triangles and polygons).
        REQUIRE_LOAD_ERROR(ply_from(file(e, "uchar uint", uint8_t(3), 0u, 1u, 0x80000000u)), "test.ply",
                           "face 0 refers to vertex 2147483648" + beyond);
        REQUIRE_LOAD_ERROR(ply_from(file(e, "uchar uint", uint8_t(3), 0u, 0xffffffffu, 1u)), "test.ply",
                           "face 0 refers to vertex 4294967295" + beyond);
        REQUIRE_LOAD_ERROR(ply_from(file(e, "uchar uint", uint8_t(4), 0u, 1u, 2u, 3000000000u)), "test.ply",
                           "face 0 refers to vertex 3000000000" + beyond);
        REQUIRE_LOAD_ERROR(ply_from(file(e, "uchar int", uint8_t(3), 0, 1, int32_t(0x80000000u))), "test.ply",
                           "face 0 refers to vertex -2147483648" + beyond);
        // A list count larger than the rest of the file, named as written.
        REQUIRE_LOAD_ERROR(ply_from(file(e, "uint int", 0xffffffffu, 0, 1, 2)), "test.ply",
                           "a list of 4294967295 values");
        REQUIRE_LOAD_ERROR(ply_from(file(e, "int int", int32_t(-5), 0, 1, 2)), "test.ply", "negative list length -5");
        // Float indices that are integers beyond 64 bits, or not integers.
        REQUIRE_LOAD_ERROR(ply_from(file(e, "uchar double", uint8_t(3), 0.0, 1.0, 1e20)), "test.ply",
                           e == Encoding::Ascii ? "'1e+20'" : "value 1e+20");
        REQUIRE_LOAD_ERROR(ply_from(file(e, "uchar double", uint8_t(3), 0.0, 1.0, 2.5)), "test.ply",
                           e == Encoding::Ascii ? "'2.5'" : "value 2.5");
    }
    // ASCII: indices and counts as written, however long.
    const std::string ascii =
        header(Encoding::Ascii, xyz + "element face 1\nproperty list uchar int vertex_indices\n") +
        "0 0 0\n1 0 0\n0 1 0\n";
    REQUIRE_LOAD_ERROR(ply_from(ascii + "3 0 1 99999999999\n"), "test.ply",
                       "face 0 refers to vertex 99999999999" + beyond);
    REQUIRE_LOAD_ERROR(ply_from(ascii + "3 0 1 99999999999999999999\n"), "test.ply", "'99999999999999999999'");
    REQUIRE_LOAD_ERROR(ply_from(ascii + "3 0 1 -99999999999999999999\n"), "test.ply", "'-99999999999999999999'");
    REQUIRE_LOAD_ERROR(ply_from(ascii + "99999999999 0 1 2\n"), "test.ply", "a list of 99999999999 values");
    REQUIRE_LOAD_ERROR(ply_from(ascii + "99999999999999999999 0 1 2\n"), "test.ply", "'99999999999999999999'");
    // Header counts beyond uint64, and beyond the 32-bit vertex numbers.
    REQUIRE_LOAD_ERROR(ply_from(header(Encoding::Ascii, xyz + "element face 18446744073709551616\n"
                                                              "property list uchar int vertex_indices\n")),
                       "test.ply", "'element face 18446744073709551616'");
    REQUIRE_LOAD_ERROR(ply_from(header(Encoding::Little, "element vertex 4294967296\nproperty float x\n"
                                                         "property float y\nproperty float z\n")),
                       "test.ply", "4294967296");
}

TEST_CASE("PLY: a uint32 index past INT_MAX among many triangles (the parallel path) names its face", "[io][ply]") {
    const int n = 70000;
    Bytes b;
    b.text(header(Encoding::Little, "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                                    "element face " + std::to_string(n) +
                                        "\nproperty list uchar uint vertex_indices\n"));
    for (const glm::vec3& p : kSquare) b.le(p.x).le(p.y).le(p.z);
    for (int i = 0; i < n; ++i) {
        b.le(uint8_t(3)).le(uint32_t(i % 4));
        b.le(uint32_t(i == 45678 ? 0x80000001u : (i + 1) % 4)).le(uint32_t((i + 2) % 4));
    }
    for (unsigned threads : {1u, 2u}) {
        set_thread_count(threads);
        REQUIRE_LOAD_ERROR(ply_from(b.str()), "test.ply",
                           "face 45678 refers to vertex 2147483649 but the file has 4 vertices");
    }
    set_thread_count(0);
}
