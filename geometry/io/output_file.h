// A file opened for writing whose every failure (cannot create, disk full,
// I/O error at close) throws MeshWriteError "PATH: problem".
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace kappa::io {

class OutputFile {
public:
    // Creates the file, or rewrites an existing one in place: cut to the
    // length written at close (or when abandoned), so it then holds exactly
    // what was written.
    explicit OutputFile(const std::string& path);
    ~OutputFile();  // cuts and closes silently if close() was not called
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    void write(const char* data, size_t size);
    void write(std::string_view text) { write(text.data(), text.size()); }
    // Flushes and closes; throws if the data could not be stored.
    void close();

private:
    [[noreturn]] void fail(const std::string& what, int error);
    bool cut_to_written();  // a longer regular file cut to written_; false on failure (errno)

    std::string path_;
    int fd_ = -1;
    size_t written_ = 0;
};

// The extension of a path's file name in lower case, without the dot ("" when
// there is none): how kappa tells the formats of its inputs and outputs.
std::string lower_extension(const std::string& path);

// Whether a file could be created at `path` (its folder exists and is
// writable), checked before any long computation: nullopt when so, else the
// reason ("no such folder 'out'").
std::optional<std::string> output_problem(const std::string& path);

}  // namespace kappa::io
