#include "file_bytes.h"

#include "io_errors.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>

namespace kappa::io {

void Unmap::operator()(char* p) const {
    if (p) ::munmap(p, size);
}

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
    void* p = ::mmap(nullptr, bytes.size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, file.fd, 0);
    if (p == MAP_FAILED) fail_load(path, std::string("cannot read: ") + std::strerror(errno));
    bytes.data = std::unique_ptr<char, Unmap>(static_cast<char*>(p), Unmap{bytes.size});
    return bytes;
}

}  // namespace kappa::io
