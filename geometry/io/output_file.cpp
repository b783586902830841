#include "output_file.h"

#include "io_errors.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cctype>
#include <cerrno>
#include <cstring>

namespace kappa::io {

// Opened without O_TRUNC: an existing file is rewritten in place and cut to
// the length written when closed (or abandoned). Truncating a big file
// first makes the kernel free every page of it and then allocate them all
// again for the new bytes: for a 55 MB PLY rewritten by the same job, 5-10%
// of `kappa curvature bunny-1M.ply`'s time (docs/speed.md).
OutputFile::OutputFile(const std::string& path) : path_(path) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) fail("cannot open for writing", errno);
}

OutputFile::~OutputFile() {
    if (fd_ < 0) return;
    cut_to_written();  // abandoned: no old bytes after the new ones
    ::close(fd_);
}

void OutputFile::write(const char* data, size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd_, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("write failed", errno);
        }
        if (n == 0) fail("write failed", EIO);
        data += n;
        size -= size_t(n);
        written_ += size_t(n);
    }
}

bool OutputFile::cut_to_written() {
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode) || size_t(st.st_size) <= written_) return true;
    return ::ftruncate(fd_, off_t(written_)) == 0;
}

void OutputFile::close() {
    if (!cut_to_written()) fail("cannot cut to length", errno);
    int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("write failed at close", errno);
}

void OutputFile::fail(const std::string& what, int error) {
    if (fd_ >= 0) {
        cut_to_written();
        ::close(fd_);
    }
    fd_ = -1;
    fail_write(path_, what + ": " + std::strerror(error));
}

std::string lower_extension(const std::string& path) {
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return "";
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

std::optional<std::string> output_problem(const std::string& path) {
    const auto slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    struct stat st {};
    if (stat(folder.c_str(), &st) != 0) return "no such folder '" + folder + "'";
    if (!S_ISDIR(st.st_mode)) return "'" + folder + "' is not a folder";
    if (access(folder.c_str(), W_OK) != 0) return "cannot write in '" + folder + "' (" + std::strerror(errno) + ")";
    struct stat file {};
    if (stat(path.c_str(), &file) == 0 && S_ISDIR(file.st_mode)) return "'" + path + "' is a folder";
    return std::nullopt;
}

}  // namespace kappa::io
