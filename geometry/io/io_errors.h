// Errors of mesh reading and writing. Every message is one line of the form
// "PATH: problem" so that callers can print what() as is.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace kappa {

struct MeshLoadError : std::runtime_error {
    using runtime_error::runtime_error;
};

struct MeshWriteError : std::runtime_error {
    using runtime_error::runtime_error;
};

namespace io {

// Throws MeshLoadError("NAME: problem").
[[noreturn]] void fail_load(const std::string& name, const std::string& problem);
// Throws MeshWriteError("PATH: problem").
[[noreturn]] void fail_write(const std::string& path, const std::string& problem);

// Text taken from a file, made safe to quote in a one-line message:
// non-printable bytes become '?', long text is cut to max_length with "...".
std::string quoted(std::string_view text, size_t max_length = 40);

}  // namespace io
}  // namespace kappa
