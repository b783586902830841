// PLY and CSV writers: round trips, the exact CSV layout of conventions.md,
// and write errors.
#include "geometry/io/output_file.h"
#include "geometry/parallel/parallel.h"
#include "test_io_support.h"
#include "test_support.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

using namespace kappa;

namespace {

// A small mesh with fields full of awkward floats (tiny, huge, negative,
// values that need all 9 significant digits).
struct Sample {
    Mesh mesh;
    SurfaceFields fields;
};

Sample make_sample(size_t n) {
    Sample s;
    uint32_t state = 12345;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        float unit = float(state >> 8) / float(1 << 24);       // [0, 1)
        float scale = std::ldexp(1.0f, int(state % 61) - 30);  // 2^-30 .. 2^30
        return (unit - 0.5f) * scale;
    };
    for (size_t i = 0; i < n; ++i) s.mesh.positions.emplace_back(next(), next(), next());
    for (uint32_t i = 0; i + 2 < n; ++i) s.mesh.faces.emplace_back(i, i + 1, i + 2);
    SurfaceFields& f = s.fields;
    for (size_t i = 0; i < n; ++i) {
        f.normals.emplace_back(next(), next(), next());
        f.k1.push_back(next());
        f.k2.push_back(next());
        f.d1.emplace_back(next(), next(), next());
        f.d2.emplace_back(next(), next(), next());
        f.dcurv.emplace_back(next(), next(), next(), next());
        f.flags.push_back(uint8_t(i * 37));
    }
    f.k1[0] = 1.0f / 3.0f;
    f.k2[0] = -0.0f;
    f.normals[0] = {1e-38f, 3.4e38f, 16777217.0f};
    return s;
}

std::vector<float> row_of(const Sample& s, size_t i) {
    const SurfaceFields& f = s.fields;
    const glm::vec3 &p = s.mesh.positions[i], &n = f.normals[i], &d1 = f.d1[i], &d2 = f.d2[i];
    const glm::vec4& c = f.dcurv[i];
    return {p.x,  p.y,  p.z,  n.x,  n.y,  n.z,  f.k1[i], f.k2[i], d1.x,
            d1.y, d1.z, d2.x, d2.y, d2.z, c[0], c[1],    c[2],    c[3]};
}

// Reads a PLY written by write_ply back with a minimal independent parser
// of its documented layout (ascii or binary little-endian).
std::vector<std::vector<float>> read_written_ply_vertices(const std::string& file, size_t n, bool binary,
                                                          std::vector<int>* flags) {
    size_t body = file.find("end_header\n") + 11;
    std::vector<std::vector<float>> rows(n, std::vector<float>(18));
    if (binary) {
        const char* p = file.data() + body;
        for (size_t i = 0; i < n; ++i) {
            std::memcpy(rows[i].data(), p, 72);
            flags->push_back(uint8_t(p[72]));
            p += 73;
        }
    } else {
        std::istringstream in(file.substr(body));
        for (size_t i = 0; i < n; ++i) {
            for (float& v : rows[i]) {
                std::string token;
                in >> token;
                v = std::strtof(token.c_str(), nullptr);
            }
            int flag;
            in >> flag;
            flags->push_back(flag);
        }
    }
    return rows;
}

}  // namespace

TEST_CASE("write_ply: binary and ascii round trips keep every number", "[io][writers]") {
    bool binary = GENERATE(true, false);
    INFO((binary ? "binary" : "ascii"));
    Sample s = make_sample(300);
    std::string path = kappa::test::temp_dir() + "/out.ply";
    write_ply(path, s.mesh, s.fields, binary);

    std::string file = kappa::test::read_file(path);
    std::string expected_header =
        std::string("ply\nformat ") + (binary ? "binary_little_endian" : "ascii") + " 1.0\n";
    CHECK(file.rfind(expected_header, 0) == 0);
    for (const char* prop :
         {"property float x\n", "property float nx\n", "property float k1\n", "property float d2z\n",
          "property float d\n", "property uchar flags\n", "property list uchar int vertex_indices\n",
          "element vertex 300\n", "element face 298\n"})
        CHECK(file.find(prop) != std::string::npos);

    // Our reader gets the same mesh back...
    Mesh back = load_mesh(path);
    CHECK(back.positions == s.mesh.positions);
    CHECK(back.faces == s.mesh.faces);
    // ...and every field value is stored exactly.
    std::vector<int> flags;
    auto rows = read_written_ply_vertices(file, 300, binary, &flags);
    for (size_t i = 0; i < 300; ++i) {
        INFO("vertex " << i);
        CHECK(rows[i] == row_of(s, i));
        CHECK(flags[i] == s.fields.flags[i]);
    }
}

TEST_CASE("write_csv: header, one row per vertex in order, %.9g values that read back exactly",
          "[io][writers]") {
    Sample s = make_sample(10000);  // more than one formatting block
    std::string path = kappa::test::temp_dir() + "/out.csv";
    write_csv(path, s.mesh, s.fields);
    std::istringstream in(kappa::test::read_file(path));
    std::string line;
    REQUIRE(std::getline(in, line));
    CHECK(line == "x,y,z,nx,ny,nz,k1,k2,d1x,d1y,d1z,d2x,d2y,d2z,a,b,c,d");
    size_t rows = 0;
    while (std::getline(in, line)) {
        REQUIRE(rows < 10000);
        std::vector<float> expected = row_of(s, rows);
        // Same text as printf("%.9g") of every value, comma-separated; a
        // zero is written 0, never -0.
        std::string printed;
        for (size_t k = 0; k < 18; ++k) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.9g", double(expected[k]) + 0.0);
            printed += (k ? "," : "") + std::string(buf);
        }
        if (line != printed) {
            INFO("row " << rows);
            REQUIRE(line == printed);
        }
        // And it reads back to the same floats.
        std::istringstream cells(line);
        std::string cell;
        for (size_t k = 0; std::getline(cells, cell, ','); ++k)
            if (std::strtof(cell.c_str(), nullptr) != expected[k]) FAIL("row " << rows << " column " << k);
        ++rows;
    }
    CHECK(rows == 10000);
}

TEST_CASE("write_csv: output is the same whatever the thread count", "[io][writers]") {
    Sample s = make_sample(20000);
    std::string dir = kappa::test::temp_dir();
    set_thread_count(1);
    write_csv(dir + "/one.csv", s.mesh, s.fields);
    set_thread_count(4);
    write_csv(dir + "/four.csv", s.mesh, s.fields);
    set_thread_count(0);
    CHECK(kappa::test::read_file(dir + "/one.csv") == kappa::test::read_file(dir + "/four.csv"));
}

TEST_CASE("writers: errors name the path (missing directory, disk full, mismatched fields)",
          "[io][writers]") {
    Sample s = make_sample(50);
    std::string bad = kappa::test::temp_dir() + "/no/such/dir/out.csv";
    auto expect_write_error = [](const std::function<void()>& write, const std::string& path,
                                 const std::string& what) {
        try {
            write();
            FAIL("expected a MeshWriteError");
        } catch (const MeshWriteError& e) {
            std::string m = e.what();
            INFO(m);
            CHECK(m.rfind(path + ": ", 0) == 0);
            CHECK(m.find(what) != std::string::npos);
            CHECK(m.find('\n') == std::string::npos);
        }
    };
    expect_write_error([&] { write_csv(bad, s.mesh, s.fields); }, bad, "cannot open for writing");
    expect_write_error([&] { write_ply(bad, s.mesh, s.fields); }, bad, "cannot open for writing");
    // /dev/full accepts the open and fails every write with ENOSPC.
    expect_write_error([&] { write_csv("/dev/full", s.mesh, s.fields); }, "/dev/full", "No space left");
    expect_write_error([&] { write_ply("/dev/full", s.mesh, s.fields, false); }, "/dev/full",
                       "No space left");
    // Binary records are written by a helper thread when there are several
    // workers (ply_writer.cpp): its failure must reach the caller the same way.
    const Sample big = make_sample(100000);  // several 1 MiB chunks
    for (unsigned threads : {1u, 2u, 3u}) {
        set_thread_count(threads);
        expect_write_error([&] { write_ply("/dev/full", big.mesh, big.fields); }, "/dev/full", "No space left");
    }
    set_thread_count(0);

    SurfaceFields short_fields = s.fields;
    short_fields.k2.pop_back();
    std::string path = kappa::test::temp_dir() + "/out.ply";
    expect_write_error([&] { write_ply(path, s.mesh, short_fields); }, path, "'k2' has 49 entries");
}

TEST_CASE("writers: an existing longer file is rewritten to exactly the new bytes", "[io][writers]") {
    // OutputFile rewrites in place (no O_TRUNC) and cuts to length: nothing
    // of the old file may survive after the new bytes, however it ends.
    const std::string dir = kappa::test::temp_dir();
    const Sample big = make_sample(5000), small = make_sample(40);
    write_ply(dir + "/fresh.ply", small.mesh, small.fields);
    write_csv(dir + "/fresh.csv", small.mesh, small.fields);
    for (const char* name : {"/over.ply", "/over.csv"}) {
        const std::string path = dir + name;
        write_ply(path, big.mesh, big.fields);  // longer than either small output
        REQUIRE(kappa::test::read_file(path).size() > 100000);
        if (std::string(name) == "/over.ply")
            write_ply(path, small.mesh, small.fields);
        else
            write_csv(path, small.mesh, small.fields);
        const std::string fresh = kappa::test::read_file(dir + (std::string(name) == "/over.ply" ? "/fresh.ply" : "/fresh.csv"));
        CHECK(kappa::test::read_file(path) == fresh);
    }
    // Abandoned (an exception while writing): cut after what was written.
    const std::string path = dir + "/abandoned.ply";
    write_ply(path, big.mesh, big.fields);
    {
        io::OutputFile file(path);
        file.write("partial");
    }
    CHECK(kappa::test::read_file(path) == "partial");
}
