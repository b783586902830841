// PLY output: the mesh with the per-vertex fields as float properties named
// after the CSV columns, plus `uchar flags`, and triangles as
// `list uchar int vertex_indices`. Written in 1 MiB chunks.
#include "ply_io.h"

#include "byte_order.h"
#include "field_columns.h"
#include "output_file.h"

#include <charconv>
#include <cstdio>
#include <cstring>
#include <limits>

namespace kappa {
namespace io {
namespace {

constexpr size_t kChunkBytes = 1 << 20;

// "comment smoothing normals 0 curvature 0 dcurv 0" with the widths used
// (%.9g), plus the noise estimate when they were chosen automatically.
std::string smoothing_comment(const SurfaceFields& fields) {
    const SmoothingOptions& s = fields.smoothing;
    char line[256];
    std::snprintf(line, sizeof line, "comment smoothing normals %.9g curvature %.9g dcurv %.9g", s.normals,
                  s.curvature, s.dcurv);
    std::string out = line;
    if (s.automatic) {
        std::snprintf(line, sizeof line, " (auto: noise sigma %.6g = %.4g median edges of %.6g)", fields.noise.sigma,
                      fields.noise.relative, fields.noise.median_edge);
        out += line;
    }
    out += "\n";
    if (s.estimator != Estimator::rusinkiewicz) out += "comment estimator " + estimator_name(s.estimator) + "\n";
    return out;
}

std::string ply_header(const Mesh& mesh, const SurfaceFields& fields, bool binary) {
    std::string h = "ply\nformat ";
    h += binary ? "binary_little_endian 1.0\n" : "ascii 1.0\n";
    h += "comment written by kappa: curvature per vertex (Rusinkiewicz 2004), columns as in kappa's README\n";
    h += smoothing_comment(fields);
    h += "element vertex " + std::to_string(mesh.vertex_count()) + "\n";
    for (const char* column : kFieldColumnNames) h += std::string("property float ") + column + "\n";
    h += "property uchar flags\n";
    h += "element face " + std::to_string(mesh.face_count()) + "\n";
    h += "property list uchar int vertex_indices\nend_header\n";
    return h;
}

// Shortest representation that reads back to the same float (0, never -0).
void append_number(std::string& out, float value) {
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value + 0.0f);
    out.append(buffer, result.ptr);
}

void append_number(std::string& out, uint32_t value) {
    char buffer[16];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

void write_vertices(OutputFile& file, const Mesh& mesh, const SurfaceFields& fields, bool binary) {
    std::string chunk;
    chunk.reserve(kChunkBytes + 1024);
    float row[kFieldColumnCount];
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
        field_row(mesh, fields, i, row);
        uint8_t flags = field_flags(fields, i);
        if (binary) {  // one append per row: 18 little-endian floats and the flags byte
            char bytes[sizeof row + 1];
            for (size_t k = 0; k < kFieldColumnCount; ++k) {
                const float v = kHostLittleEndian ? row[k] : byte_swapped(row[k]);
                std::memcpy(bytes + 4 * k, &v, 4);
            }
            bytes[sizeof row] = char(flags);
            chunk.append(bytes, sizeof bytes);
        } else {
            for (float v : row) {
                append_number(chunk, v);
                chunk.push_back(' ');
            }
            append_number(chunk, uint32_t(flags));
            chunk.push_back('\n');
        }
        if (chunk.size() >= kChunkBytes) {
            file.write(chunk);
            chunk.clear();
        }
    }
    file.write(chunk);
}

void write_faces(OutputFile& file, const Mesh& mesh, bool binary) {
    std::string chunk;
    chunk.reserve(kChunkBytes + 1024);
    for (const Face& f : mesh.faces) {
        if (binary) {  // one append per face: the count and three little-endian indices
            char bytes[13];
            bytes[0] = char(3);
            for (int k = 0; k < 3; ++k) {
                const int32_t v = kHostLittleEndian ? int32_t(f[k]) : byte_swapped(int32_t(f[k]));
                std::memcpy(bytes + 1 + 4 * k, &v, 4);
            }
            chunk.append(bytes, sizeof bytes);
        } else {
            chunk += "3";
            for (int k = 0; k < 3; ++k) {
                chunk.push_back(' ');
                append_number(chunk, f[k]);
            }
            chunk.push_back('\n');
        }
        if (chunk.size() >= kChunkBytes) {
            file.write(chunk);
            chunk.clear();
        }
    }
    file.write(chunk);
}

}  // namespace
}  // namespace io

void write_ply(const std::string& path, const Mesh& mesh, const SurfaceFields& fields, bool binary) {
    using namespace io;
    check_fields_match(path, mesh, fields);
    if (mesh.vertex_count() > size_t(std::numeric_limits<int32_t>::max()))
        fail_write(path, "too many vertices for 32-bit PLY indices");
    OutputFile file(path);
    file.write(ply_header(mesh, fields, binary));
    write_vertices(file, mesh, fields, binary);
    write_faces(file, mesh, binary);
    file.close();
}

}  // namespace kappa
