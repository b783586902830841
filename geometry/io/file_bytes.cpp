#include "file_bytes.h"

#include "io_errors.h"
#include "prefault.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>

namespace kappa::io {

namespace {
// Closes the descriptor on every path out of read_file_bytes.
struct FdGuard {
    int fd;
    ~FdGuard() {
        if (fd >= 0) ::close(fd);
    }
};
}  // namespace

FileBytes read_file_bytes(const std::string& path) {
    FdGuard file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
    if (file.fd < 0) {
        int err = errno;
        if (err == ENOENT) fail_load(path, "no such file");
        fail_load(path, std::string("cannot open: ") + std::strerror(err));
    }
    struct stat st {};
    if (::fstat(file.fd, &st) != 0) fail_load(path, std::string("cannot stat: ") + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) fail_load(path, "is a directory, not a mesh file");
    if (!S_ISREG(st.st_mode)) fail_load(path, "is not a regular file");
    if (st.st_size == 0) fail_load(path, "file is empty");

    FileBytes bytes;
    bytes.size = static_cast<size_t>(st.st_size);
    try {
        bytes.data.reset(new char[bytes.size]);  // uninitialised: filled by read()
    } catch (const std::bad_alloc&) {
        fail_load(path, "file too large to read into memory");
    }
    prefault(bytes.data.get(), bytes.size);
    size_t done = 0;
    while (done < bytes.size) {
        ssize_t n = ::read(file.fd, bytes.data.get() + done, bytes.size - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail_load(path, std::string("read error: ") + std::strerror(errno));
        }
        if (n == 0) fail_load(path, "file shrank while being read");
        done += static_cast<size_t>(n);
    }
    return bytes;
}

}  // namespace kappa::io
