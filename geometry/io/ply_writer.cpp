// PLY output: the mesh with the per-vertex fields as float properties named
// after the CSV columns, plus `uchar flags`, and triangles as
// `list uchar int vertex_indices`. Written in 1 MiB chunks.
#include "ply_io.h"


#include "byte_order.h"
#include "field_columns.h"
#include "output_file.h"

#include "geometry/io/float_chars.h"
#include "geometry/parallel/parallel.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <limits>
#include <exception>
#include <thread>
#include <vector>

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
    out.append(buffer, float_to_chars(buffer, buffer + sizeof buffer, value + 0.0f));
}

void append_number(std::string& out, uint32_t value) {
    char buffer[16];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

// A binary block of `count` fixed-size records: format(i, out) writes
// record i's `record_bytes` bytes. The worker threads fill a few 1 MiB
// chunks at a time, which are written in order; with more than one worker,
// a helper thread writes each batch while the workers fill the next (the
// system call copies into the page cache on one thread only).
template <typename Format>
void write_records(OutputFile& file, size_t count, size_t record_bytes, const Format& format) {
    const size_t per_chunk = std::max<size_t>(1, kChunkBytes / record_bytes);
    const size_t chunks = (count + per_chunk - 1) / per_chunk;
    const bool overlap = thread_count() > 1;
    using Batch = std::vector<std::vector<char>>;
    Batch batches[2] = {Batch(2 * size_t(thread_count())), Batch(overlap ? 2 * size_t(thread_count()) : 0)};
    const size_t per_batch = batches[0].size();
    std::thread writer;
    std::exception_ptr write_error;
    const auto write_batch = [&file, &write_error](const Batch& batch, size_t n) {
        try {
            for (size_t k = 0; k < n; ++k) file.write(batch[k].data(), batch[k].size());
        } catch (...) {
            write_error = std::current_exception();
        }
    };
    const auto finish_writing = [&] {
        if (writer.joinable()) writer.join();
        if (write_error) std::rethrow_exception(write_error);
    };
    struct Join {  // never leave the writer running (format may throw)
        std::thread& thread;
        ~Join() {
            if (thread.joinable()) thread.join();
        }
    } join{writer};
    for (size_t first = 0, b = 0; first < chunks; first += per_batch, b ^= size_t(overlap)) {
        Batch& buffers = batches[b];
        const size_t n = std::min(per_batch, chunks - first);
        parallel_for_ranges(
            n,
            [&](size_t begin, size_t end) {
                for (size_t k = begin; k < end; ++k) {
                    const size_t from = (first + k) * per_chunk, to = std::min(count, from + per_chunk);
                    buffers[k].resize((to - from) * record_bytes);
                    for (size_t i = from; i < to; ++i) format(i, buffers[k].data() + (i - from) * record_bytes);
                }
            },
            1);
        finish_writing();  // the previous batch, written from the other set of buffers
        if (overlap) {
            writer = std::thread(write_batch, std::cref(buffers), n);
        } else {
            write_batch(buffers, n);
            finish_writing();
        }
    }
    finish_writing();
}

// The 18 column values as little-endian floats, then the flags byte.
void write_binary_vertices(OutputFile& file, const Mesh& mesh, const SurfaceFields& fields) {
    constexpr size_t kRecord = 4 * kFieldColumnCount + 1;
    write_records(file, mesh.vertex_count(), kRecord, [&](size_t i, char* out) {
        float row[kFieldColumnCount];
        field_row(mesh, fields, i, row);
        if (!kHostLittleEndian)
            for (float& v : row) v = byte_swapped(v);
        std::memcpy(out, row, sizeof row);
        out[sizeof row] = char(field_flags(fields, i));
    });
}

// The vertex count 3, then three little-endian int32 indices.
void write_binary_faces(OutputFile& file, const Mesh& mesh) {
    write_records(file, mesh.face_count(), 13, [&](size_t i, char* out) {
        int32_t v[3];
        for (int k = 0; k < 3; ++k) v[k] = kHostLittleEndian ? int32_t(mesh.faces[i][k]) : byte_swapped(int32_t(mesh.faces[i][k]));
        out[0] = char(3);
        std::memcpy(out + 1, v, sizeof v);
    });
}

void write_text_vertices(OutputFile& file, const Mesh& mesh, const SurfaceFields& fields) {
    std::string chunk;
    chunk.reserve(kChunkBytes + 1024);
    float row[kFieldColumnCount];
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
        field_row(mesh, fields, i, row);
        for (float v : row) {
            append_number(chunk, v);
            chunk.push_back(' ');
        }
        append_number(chunk, uint32_t(field_flags(fields, i)));
        chunk.push_back('\n');
        if (chunk.size() >= kChunkBytes) {
            file.write(chunk);
            chunk.clear();
        }
    }
    file.write(chunk);
}

void write_text_faces(OutputFile& file, const Mesh& mesh) {
    std::string chunk;
    chunk.reserve(kChunkBytes + 1024);
    for (const Face& f : mesh.faces) {
        chunk += "3";
        for (int k = 0; k < 3; ++k) {
            chunk.push_back(' ');
            append_number(chunk, f[k]);
        }
        chunk.push_back('\n');
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
    if (binary) {
        write_binary_vertices(file, mesh, fields);
        write_binary_faces(file, mesh);
    } else {
        write_text_vertices(file, mesh, fields);
        write_text_faces(file, mesh);
    }
    file.close();
}

}  // namespace kappa
