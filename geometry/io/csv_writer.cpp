// Rows are formatted in parallel, in fixed blocks of rows, and written in
// order, so the output does not depend on the thread count.
#include "csv_io.h"

#include "geometry/io/float_chars.h"
#include "geometry/parallel/parallel.h"
#include "field_columns.h"
#include "output_file.h"

#include <charconv>
#include <vector>

namespace kappa {
namespace io {
namespace {

constexpr size_t kRowsPerBlock = 4096;
constexpr size_t kBlocksPerBatch = 64;  // ~45 MB of text at most in memory

// Formats rows [begin, end) into out: "%.9g" is to_chars' general format
// with precision 9 (the C++ standard defines it as printf's).
void format_rows(const Mesh& mesh, const SurfaceFields& fields, size_t begin, size_t end, std::string& out) {
    out.clear();
    out.resize((end - begin) * kFieldColumnCount * 17);  // at most 16 characters + separator each
    char* p = out.data();
    char* const limit = p + out.size();
    float row[kFieldColumnCount];
    for (size_t i = begin; i < end; ++i) {
        field_row(mesh, fields, i, row);
        for (size_t k = 0; k < kFieldColumnCount; ++k) {
            // + 0.0f turns -0 into 0: a zero is written as 0, never -0.
            p = float_to_chars(p, limit, row[k] + 0.0f, 9);
            *p++ = k + 1 < kFieldColumnCount ? ',' : '\n';
        }
    }
    out.resize(size_t(p - out.data()));
}

std::string csv_header() {
    std::string h;
    for (size_t k = 0; k < kFieldColumnCount; ++k) {
        h += kFieldColumnNames[k];
        h += k + 1 < kFieldColumnCount ? ',' : '\n';
    }
    return h;
}

}  // namespace
}  // namespace io

void write_csv(const std::string& path, const Mesh& mesh, const SurfaceFields& fields) {
    using namespace io;
    check_fields_match(path, mesh, fields);
    OutputFile file(path);
    file.write(csv_header());
    const size_t n = mesh.vertex_count();
    std::vector<std::string> blocks(kBlocksPerBatch);
    for (size_t batch = 0; batch < n; batch += kRowsPerBlock * kBlocksPerBatch) {
        size_t block_count = std::min(kBlocksPerBatch, (n - batch + kRowsPerBlock - 1) / kRowsPerBlock);
        parallel_for(
            block_count,
            [&](size_t b) {
                size_t begin = batch + b * kRowsPerBlock;
                format_rows(mesh, fields, begin, std::min(n, begin + kRowsPerBlock), blocks[b]);
            },
            1);
        for (size_t b = 0; b < block_count; ++b) file.write(blocks[b]);
    }
    file.close();
}

}  // namespace kappa
