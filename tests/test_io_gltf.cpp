// glTF 2.0 reading (geometry/io/gltf_io.h): small files written here, as
// JSON with an embedded base64 buffer or as a .glb container; every
// triangle mode, indices, node transforms, scenes, and one-line errors.
#include "test_support.h"

#include "geometry/io/mesh_io.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace kappa;
using kappa::test::base64;

namespace {

template <typename T>
std::string bytes_of(const std::vector<T>& v) {
    return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// One mesh with one primitive: positions (float VEC3), optional uint16 (or
// uint32: wide_indices) indices, a mode; `nodes` and `scenes` JSON given by the test (the mesh is 0).
struct Gltf {
    std::vector<float> positions;
    std::vector<uint16_t> indices;
    std::vector<uint32_t> wide_indices;
    int mode = 4;
    std::string nodes = R"([{"mesh": 0}])";
    std::string scenes = R"("scene": 0, "scenes": [{"nodes": [0]}])";
    std::string extra_accessor;  // replaces the indices accessor when set

    // The JSON, with the buffer as a data URI (uri empty: for a .glb BIN chunk).
    std::string index_bytes() const { return bytes_of(indices) + bytes_of(wide_indices); }
    size_t index_count() const { return indices.size() + wide_indices.size(); }

    std::string json(bool embedded = true) const {
        const std::string buffer = bytes_of(positions) + index_bytes();
        const size_t vertex_bytes = positions.size() * 4;
        float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
        for (size_t i = 0; i < positions.size(); ++i)
            lo[i % 3] = std::min(lo[i % 3], positions[i]), hi[i % 3] = std::max(hi[i % 3], positions[i]);
        std::string j = R"({"asset": {"version": "2.0"}, )" + scenes + R"(, "nodes": )" + nodes + ", ";
        j += R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": )" + std::to_string(mode);
        if (index_count() || !extra_accessor.empty()) j += R"(, "indices": 1)";
        j += "}]}], ";
        j += R"("buffers": [{"byteLength": )" + std::to_string(buffer.size());
        if (embedded) j += R"(, "uri": "data:application/octet-stream;base64,)" + base64(buffer) + "\"";
        j += "}], ";
        j += R"("bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" + std::to_string(vertex_bytes) + "}";
        if (index_count())
            j += R"(, {"buffer": 0, "byteOffset": )" + std::to_string(vertex_bytes) + R"(, "byteLength": )" +
                 std::to_string(index_bytes().size()) + "}";
        j += "], ";
        char bounds[200];
        std::snprintf(bounds, sizeof bounds, R"("min": [%g, %g, %g], "max": [%g, %g, %g])", lo[0], lo[1], lo[2],
                      hi[0], hi[1], hi[2]);
        j += R"("accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": )" +
             std::to_string(positions.size() / 3) + ", " + bounds + "}";
        if (!extra_accessor.empty()) j += ", " + extra_accessor;
        else if (index_count())
            j += R"(, {"bufferView": 1, "componentType": )" + std::string(indices.empty() ? "5125" : "5123") +
                 R"(, "type": "SCALAR", "count": )" + std::to_string(index_count()) + "}";
        j += "]}";
        return j;
    }

    // The same as a .glb: header, JSON chunk, BIN chunk (4-byte aligned).
    std::string glb() const {
        std::string j = json(false), bin = bytes_of(positions) + index_bytes();
        while (j.size() % 4) j += ' ';
        while (bin.size() % 4) bin += '\0';
        auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
        std::string out = "glTF" + u32(2) + u32(uint32_t(12 + 8 + j.size() + 8 + bin.size()));
        out += u32(uint32_t(j.size())) + "JSON" + j;
        out += u32(uint32_t(bin.size())) + std::string("BIN\0", 4) + bin;
        return out;
    }
};

Mesh load(const std::string& name, const std::string& contents) {
    const std::string path = test::temp_dir() + "/" + name;
    test::write_file(path, contents);
    return load_mesh(path);
}

glm::vec3 face_normal(const Mesh& m, size_t f) {
    const Face& t = m.faces[f];
    return glm::normalize(glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
}

// The cube [-1, 1]^3: 8 corners (corner i has x, y, z = -1 or 1 by bits 0,
// 1, 2 of i) and 12 triangles, counter-clockwise seen from outside.
Gltf cube() {
    Gltf g;
    for (int i = 0; i < 8; ++i)
        for (int a = 0; a < 3; ++a) g.positions.push_back(i >> a & 1 ? 1.0f : -1.0f);
    g.indices = {0, 2, 3, 0, 3, 1,  4, 5, 7, 4, 7, 6,  0, 1, 5, 0, 5, 4,
                 2, 6, 7, 2, 7, 3,  0, 4, 6, 0, 6, 2,  1, 3, 7, 1, 7, 5};
    return g;
}

glm::vec3 face_centroid(const Mesh& m, size_t f) {
    const Face& t = m.faces[f];
    return (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0f;
}

// The index of the centre nearest to face f's centroid: which instance the face belongs to.
size_t instance_of(const Mesh& m, size_t f, const std::vector<glm::vec3>& centres) {
    size_t best = 0;
    for (size_t k = 1; k < centres.size(); ++k)
        if (glm::length(face_centroid(m, f) - centres[k]) < glm::length(face_centroid(m, f) - centres[best])) best = k;
    return best;
}

// Per instance: the signed volume enclosed by its faces (positive when they
// are counter-clockwise seen from outside) and how many of its faces have a
// normal pointing towards the instance's centre.
struct Orientation {
    std::vector<double> volume;
    std::vector<int> inward;
};
Orientation orientation(const Mesh& m, const std::vector<glm::vec3>& centres) {
    Orientation o{std::vector<double>(centres.size(), 0.0), std::vector<int>(centres.size(), 0)};
    for (size_t f = 0; f < m.face_count(); ++f) {
        const size_t k = instance_of(m, f, centres);
        const Face& t = m.faces[f];
        const glm::dvec3 a = glm::dvec3(m.positions[t[0]] - centres[k]), b = glm::dvec3(m.positions[t[1]] - centres[k]),
                         c = glm::dvec3(m.positions[t[2]] - centres[k]);
        o.volume[k] += glm::dot(a, glm::cross(b, c)) / 6.0;
        if (glm::dot(face_normal(m, f), face_centroid(m, f) - centres[k]) <= 0.0f) ++o.inward[k];
    }
    return o;
}

std::string load_error(const std::string& name, const std::string& contents) {
    try {
        load(name, contents);
    } catch (const MeshLoadError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("glTF: a triangle list, indexed or not, reads with its winding", "[io][gltf]") {
    Gltf g;
    g.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const Mesh tri = load("tri.gltf", g.json());
    REQUIRE(tri.vertex_count() == 3);
    REQUIRE(tri.face_count() == 1);
    CHECK(tri.positions[1] == glm::vec3(1, 0, 0));
    CHECK(face_normal(tri, 0).z == Approx(1));  // counter-clockwise seen from +z

    Gltf quad;
    quad.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    quad.indices = {0, 1, 2, 0, 2, 3};
    const Mesh q = load("quad.gltf", quad.json());
    CHECK(q.vertex_count() == 4);
    REQUIRE(q.face_count() == 2);
    CHECK(face_normal(q, 0).z == Approx(1));
    CHECK(face_normal(q, 1).z == Approx(1));
}

TEST_CASE("glTF: strips alternate their order and fans turn about the first vertex", "[io][gltf]") {
    Gltf strip;
    strip.positions = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 2, 0, 0};  // a zig-zag strip of 3 triangles
    strip.mode = 5;
    const Mesh s = load("strip.gltf", strip.json());
    REQUIRE(s.face_count() == 3);
    for (size_t f = 0; f < 3; ++f) CHECK(face_normal(s, f).z == Approx(-1));  // one orientation throughout

    Gltf fan;
    fan.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 1, 0};
    fan.mode = 6;
    const Mesh f = load("fan.gltf", fan.json());
    REQUIRE(f.face_count() == 3);
    for (size_t k = 0; k < 3; ++k) {
        CHECK(f.faces[k][0] == 0);
        CHECK(face_normal(f, k).z == Approx(1));
    }

    Gltf points = fan;
    points.mode = 0;  // points only: nothing to draw
    CHECK(load_error("points.gltf", points.json()).find("no triangles") != std::string::npos);
}

TEST_CASE("glTF: node transforms apply, parents first, and a mesh used twice is placed twice", "[io][gltf]") {
    Gltf g;
    g.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    // Node 0: translated by (10, 0, 0), child node 1 scales by 2 then turns 90 degrees about z.
    g.nodes = R"([{"translation": [10, 0, 0], "children": [1]},
                  {"mesh": 0, "rotation": [0, 0, 0.70710678, 0.70710678], "scale": [2, 2, 2]},
                  {"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,5,1]}])";
    g.scenes = R"("scenes": [{"nodes": [0, 2]}])";
    const Mesh m = load("nodes.gltf", g.json());
    REQUIRE(m.face_count() == 2);
    REQUIRE(m.vertex_count() == 6);
    // (1, 0, 0) scaled to (2, 0, 0), turned to (0, 2, 0), moved to (10, 2, 0).
    CHECK(glm::length(m.positions[1] - glm::vec3(10, 2, 0)) < 1e-5f);
    CHECK(glm::length(m.positions[4] - glm::vec3(1, 0, 5)) < 1e-5f);  // the matrix node: z + 5
}

// glTF 2.0, 3.7.2.1: "When a mesh primitive uses any triangle-based topology,
// the determinant of the node's global transform defines the winding order of
// that primitive": counter-clockwise if positive, clockwise if negative.
TEST_CASE("glTF: a mirrored cube (scale -1 in x) loads with outward faces", "[io][gltf]") {
    Gltf g = cube();
    g.nodes = R"([{"mesh": 0, "scale": [-1, 1, 1]}])";
    const Mesh m = load("mirrored-cube.gltf", g.json());
    REQUIRE(m.vertex_count() == 8);
    REQUIRE(m.face_count() == 12);
    const Orientation o = orientation(m, {glm::vec3(0)});
    CHECK(o.volume[0] == Approx(8.0));  // inward faces would give -8
    CHECK(o.inward[0] == 0);

    // The same through a .glb, and with the mirror in a node matrix.
    CHECK(orientation(load("mirrored-cube.glb", g.glb()), {glm::vec3(0)}).volume[0] == Approx(8.0));
    g.nodes = R"([{"mesh": 0, "matrix": [-1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])";
    CHECK(orientation(load("matrix-mirror.gltf", g.json()), {glm::vec3(0)}).volume[0] == Approx(8.0));
}

TEST_CASE("glTF: plain and mirrored instances of one mesh in a scene are all outward", "[io][gltf]") {
    Gltf g = cube();
    // 0: plain; 1: mirrored by its own scale; 3: mirrored by its parent's
    // matrix (2); 5: mirrored by its parent (4) and again by its own scale,
    // so its global transform keeps the winding.
    g.nodes = R"([{"mesh": 0, "translation": [-3, 0, 0]},
                  {"mesh": 0, "translation": [3, 0, 0], "scale": [-1, 1, 1]},
                  {"matrix": [1,0,0,0, 0,1,0,0, 0,0,-1,0, 0,4,0,1], "children": [3]},
                  {"mesh": 0},
                  {"translation": [0, -4, 0], "scale": [-1, 1, 1], "children": [5]},
                  {"mesh": 0, "scale": [1, -1, 1]}])";
    g.scenes = R"("scene": 0, "scenes": [{"nodes": [0, 1, 2, 4]}])";
    const Mesh m = load("instances.gltf", g.json());
    REQUIRE(m.vertex_count() == 32);
    REQUIRE(m.face_count() == 48);
    const std::vector<glm::vec3> centres = {{-3, 0, 0}, {3, 0, 0}, {0, 4, 0}, {0, -4, 0}};
    const Orientation o = orientation(m, centres);
    for (size_t k = 0; k < centres.size(); ++k) {
        INFO("instance " << k);
        CHECK(o.volume[k] == Approx(8.0));
        CHECK(o.inward[k] == 0);
    }
}

TEST_CASE("glTF: rotation with non-uniform scale places every vertex and keeps faces outward", "[io][gltf]") {
    Gltf g = cube();
    // Both nodes: translation t, rotation of 0.7 rad about (1, 2, 3), scale s;
    // node 0's scale has one negative factor (a mirror), node 1's none.
    const double angle = 0.7, half = angle / 2;
    const glm::dvec3 axis = glm::normalize(glm::dvec3(1, 2, 3));
    const glm::dvec3 q = axis * std::sin(half);
    char rotation[160];
    std::snprintf(rotation, sizeof rotation, "[%.17g, %.17g, %.17g, %.17g]", q.x, q.y, q.z, std::cos(half));
    g.nodes = std::string(R"([{"mesh": 0, "translation": [1, 2, 3], "scale": [2, -0.5, 3], "rotation": )") +
              rotation + R"(}, {"mesh": 0, "translation": [20, 2, 3], "scale": [2, 0.5, 3], "rotation": )" +
              rotation + "}]";
    g.scenes = R"("scene": 0, "scenes": [{"nodes": [0, 1]}])";
    const Mesh m = load("rotated.gltf", g.json());
    REQUIRE(m.vertex_count() == 16);
    REQUIRE(m.face_count() == 24);

    // Rodrigues' rotation matrix, written out independently of the reader's quaternion code.
    const double c = std::cos(angle), s = std::sin(angle);
    const glm::dmat3 K(0, axis.z, -axis.y, -axis.z, 0, axis.x, axis.y, -axis.x, 0);  // columns: K v = axis x v
    const glm::dmat3 R = glm::dmat3(1.0) + s * K + (1 - c) * K * K;
    const glm::dvec3 translations[2] = {{1, 2, 3}, {20, 2, 3}};
    const glm::dvec3 scales[2] = {{2, -0.5, 3}, {2, 0.5, 3}};
    for (int node = 0; node < 2; ++node) {
        INFO("node " << node);
        const glm::dmat3 M = R * glm::dmat3(scales[node].x, 0, 0, 0, scales[node].y, 0, 0, 0, scales[node].z);
        // Every corner at t + R S p, within float rounding.
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 p(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
            const glm::vec3 expected(translations[node] + M * p);
            double nearest = 1e30;
            for (const glm::vec3& v : m.positions) nearest = std::min(nearest, double(glm::length(v - expected)));
            INFO("corner " << i);
            CHECK(nearest < 1e-5);
        }
        // Outward: volume 8 |det M|, and each face normal is the inverse
        // transpose of M applied to the untransformed cube's outward normal.
        const Orientation o = orientation(m, {glm::vec3(translations[0]), glm::vec3(translations[1])});
        CHECK(o.volume[size_t(node)] == Approx(8.0 * std::abs(glm::determinant(M))));
        CHECK(o.inward[size_t(node)] == 0);
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(M));
        for (size_t f = 0; f < m.face_count(); ++f) {
            if (instance_of(m, f, {glm::vec3(translations[0]), glm::vec3(translations[1])}) != size_t(node)) continue;
            // The untransformed face: its centroid has one coordinate at +-1
            // (the face's side), the others at +-1/3.
            const glm::dvec3 local = glm::inverse(M) * (glm::dvec3(face_centroid(m, f)) - translations[node]);
            int side = 0;
            for (int a = 1; a < 3; ++a)
                if (std::abs(local[a]) > std::abs(local[side])) side = a;
            glm::dvec3 n0(0);
            n0[side] = local[side] > 0 ? 1 : -1;
            const glm::dvec3 expected = glm::normalize(normal_matrix * n0);
            INFO("face " << f);
            CHECK(glm::dot(glm::dvec3(face_normal(m, f)), expected) > 0.99999);
        }
    }
}

TEST_CASE("glTF: the default scene is the one named by scene", "[io][gltf]") {
    Gltf g;
    g.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    g.nodes = R"([{"mesh": 0}, {"mesh": 0, "translation": [0, 0, 3]}])";
    g.scenes = R"("scene": 1, "scenes": [{"nodes": [0]}, {"nodes": [1]}])";
    const Mesh m = load("scenes.gltf", g.json());
    REQUIRE(m.vertex_count() == 3);
    CHECK(m.positions[0].z == 3.0f);
}

TEST_CASE("glTF: the binary container reads like the JSON, found by its magic too", "[io][gltf]") {
    Gltf quad;
    quad.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    quad.indices = {0, 1, 2, 0, 2, 3};
    const Mesh a = load("quad.glb", quad.glb());
    const Mesh b = load("quad-without-extension", quad.glb());
    const Mesh c = load("quad.gltf", quad.json());
    CHECK(a.faces == c.faces);
    CHECK(a.positions == c.positions);
    CHECK(b.faces == c.faces);

    // An external buffer file next to the .gltf.
    const std::string dir = test::temp_dir();
    std::string external = quad.json(false);
    external.replace(external.find(R"("byteLength": 60)"), 16, R"("byteLength": 60, "uri": "quad.bin")");
    test::write_file(dir + "/quad.bin", bytes_of(quad.positions) + bytes_of(quad.indices));
    test::write_file(dir + "/external.gltf", external);
    const Mesh d = load_mesh(dir + "/external.gltf");
    CHECK(d.faces == c.faces);
    CHECK(d.positions == c.positions);
}

TEST_CASE("glTF: bad files are one-line errors naming the file", "[io][gltf]") {
    Gltf g;
    g.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    g.indices = {0, 1, 7};
    const std::string range = load_error("range.gltf", g.json());
    CHECK(range.find("range.gltf") != std::string::npos);
    CHECK(range.find("index 7 out of range") != std::string::npos);

    Gltf outside;
    outside.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    outside.extra_accessor = R"({"bufferView": 0, "byteOffset": 32, "componentType": 5123, "type": "SCALAR", "count": 3})";
    CHECK(load_error("outside.gltf", outside.json()).find("outside its buffer") != std::string::npos);

    // Found by fuzz_gltf: a POSITION naming an accessor that does not exist.
    Gltf missing;
    missing.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::string text = missing.json();
    text.replace(text.find(R"("POSITION": 0)"), 13, R"("POSITION": 5)");
    CHECK(load_error("missing.gltf", text).find("POSITION: no such accessor") != std::string::npos);

    // Found by fuzz_gltf: a transform that sends positions to infinity.
    Gltf huge;
    huge.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    huge.nodes = R"([{"mesh": 0, "scale": [1e39, 1, 1]}])";
    CHECK(load_error("huge.gltf", huge.json()).find("not finite") != std::string::npos);

    // Found by fuzz_gltf: a buffer whose uri names a folder (or nothing readable).
    Gltf folder;
    folder.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::string external = folder.json(false);
    external.replace(external.find(R"("byteLength": 36)"), 16, R"("byteLength": 36, "uri": ".")");
    const std::string folder_error = load_error("folder.gltf", external);
    CHECK(folder_error.find("folder.gltf: glTF") != std::string::npos);

    const std::string json = load_error("broken.gltf", R"({"asset": {"version": "2.0"}, "meshes": [)");
    CHECK(json.find("broken.gltf: glTF") != std::string::npos);
    for (const std::string& e : {range, json}) CHECK(std::count(e.begin(), e.end(), '\n') == 0);
}

TEST_CASE("glTF: indices and counts beyond the vertices or whose byte size overflows are errors quoting them",
          "[io][gltf]") {
    // The one-line error "PATH: problem" loading `text` as `name`, with `fragment` in it.
    auto check_error = [](const std::string& name, const std::string& text, const std::string& fragment) {
        const std::string e = load_error(name, text);
        INFO("message: " << e);
        CHECK(e.find("/" + name + ": ") != std::string::npos);
        CHECK(e.find(fragment) != std::string::npos);
        CHECK(std::count(e.begin(), e.end(), '\n') == 0);
    };
    Gltf triangle;
    triangle.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::string huge = "4611686018427387905";  // 2^62 + 1: times 4 or 12, 0 modulo 2^64

    SECTION("a uint32 index past INT_MAX or past the vertex count, as written") {
        Gltf wide = triangle;
        for (uint32_t k : {3u, 0x80000000u, 0xffffffffu}) {
            wide.wide_indices = {0, k, 1};
            check_error("wide.gltf", wide.json(),
                        "index " + std::to_string(k) + " out of range (POSITION has 3 vertices)");
        }
        wide.wide_indices = {0, 1, 2};
        CHECK(load("wide.gltf", wide.json()).face_count() == 1);
    }
    // Counts whose byte size, (count - 1) * stride + element size, overflows
    // 64 bits: it wrapped round to a few bytes inside the buffer and passed
    // the bounds check (then std::length_error from a vector of 2^62 elements).
    SECTION("a POSITION count whose byte size overflows") {
        std::string text = triangle.json();
        const size_t at = text.find(R"("count": 3)");
        REQUIRE(at != std::string::npos);
        text.replace(at, 10, R"("count": )" + huge);
        check_error("positions.gltf", text, "POSITION: accessor of " + huge + " elements reaches outside its buffer");
    }
    SECTION("an index count whose byte size overflows") {
        Gltf g = triangle;
        g.extra_accessor = R"({"bufferView": 0, "componentType": 5125, "type": "SCALAR", "count": )" + huge + "}";
        check_error("indices.gltf", g.json(), "indices: accessor of " + huge + " elements reaches outside its buffer");
    }
    SECTION("byte offsets whose sum wraps round") {
        Gltf g = triangle;
        g.positions.insert(g.positions.end(), {0, 0, 1});
        g.extra_accessor = R"({"bufferView": 0, "byteOffset": 18446744073709551612, "componentType": 5125, )"
                           R"("type": "SCALAR", "count": 3})";
        check_error("offset.gltf", g.json(), "indices: accessor of 3 elements reaches outside its buffer");
        // A buffer view's byteOffset plus its accessor's wrapping round to the
        // buffer's start: the indices were read from the positions' bytes.
        Gltf v = triangle;
        v.extra_accessor = R"({"bufferView": 1, "byteOffset": 8, "componentType": 5125, "type": "SCALAR", "count": 3})";
        std::string text = v.json();
        const size_t views_end = text.find(R"(], "accessors")");
        REQUIRE(views_end != std::string::npos);
        text.insert(views_end, R"(, {"buffer": 0, "byteOffset": 18446744073709551608, "byteLength": 36})");
        check_error("view.gltf", text, "indices: accessor of 3 elements reaches outside its buffer");
    }
    SECTION("a file of 4 GiB or more") {
        // tinygltf takes the size as a 32-bit unsigned: it was cut to its low
        // 32 bits and the file read as if it ended there. (The size here is
        // not backed by memory: the reader must refuse it before reading.)
        const std::string small = triangle.json();
        const size_t size = (size_t(1) << 32) + small.size();
        try {
            read_gltf(small.data(), size, "big.gltf");
            FAIL("a 4 GiB glTF file was read");
        } catch (const MeshLoadError& e) {
            CHECK(std::string(e.what()) == "big.gltf: glTF: the file has " + std::to_string(size) +
                                               " bytes, more than tinygltf can read (4 GiB - 1)");
        }
    }
}
