// Whole-file reading: mesh readers parse from memory, so a file is read in
// one go (at disk or page-cache speed) and then parsed without further I/O.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

namespace kappa::io {

struct FileBytes {
    std::unique_ptr<char[]> data;  // not NUL-terminated
    size_t size = 0;
};

// Reads a regular file completely. Throws MeshLoadError "PATH: problem" for a
// missing, unreadable or empty file, a directory, or a short read.
FileBytes read_file_bytes(const std::string& path);

}  // namespace kappa::io
