// Whole-file reading: mesh readers parse from memory, so a file is mapped in
// one go (at disk or page-cache speed) and then parsed without further I/O.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

namespace kappa::io {

// Unmaps the file's pages.
struct Unmap {
    size_t size = 0;
    void operator()(char* p) const;
};

struct FileBytes {
    std::unique_ptr<char, Unmap> data;  // read-only, not NUL-terminated
    size_t size = 0;
};

// Maps a regular file completely, read-only and private, its pages mapped
// up front (MAP_POPULATE): the page cache's own pages, with no copy and no
// fresh memory to zero (which on a VM costs more than the copy). The file
// must not be truncated while the bytes are in use. Throws MeshLoadError "PATH: problem" for a
// missing, unreadable or empty file, a directory, or a short read.
FileBytes read_file_bytes(const std::string& path);

}  // namespace kappa::io
