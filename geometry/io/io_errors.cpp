#include "io_errors.h"

namespace kappa::io {

namespace {
// Messages must stay on one line whatever the path or the file contained.
std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}
}  // namespace

void fail_load(const std::string& name, const std::string& problem) {
    throw MeshLoadError(one_line(name + ": " + problem));
}

void fail_write(const std::string& path, const std::string& problem) {
    throw MeshWriteError(one_line(path + ": " + problem));
}

std::string quoted(std::string_view text, size_t max_length) {
    std::string out = "'";
    for (size_t i = 0; i < text.size() && i < max_length; ++i) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        out += (c >= 0x20 && c < 0x7f) ? char(c) : '?';
    }
    if (text.size() > max_length) out += "...";
    return out + "'";
}

}  // namespace kappa::io
