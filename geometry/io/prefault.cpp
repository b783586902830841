#include "prefault.h"

#include <sys/mman.h>
#include <unistd.h>
#include <cstdint>

#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23  // Linux 5.14
#endif

namespace kappa::io {

void prefault(void* data, size_t bytes) {
    constexpr size_t kMinBytes = 1 << 20;
    if (bytes < kMinBytes) return;
    const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
    uintptr_t begin = (uintptr_t(data) + page - 1) & ~(page - 1);
    uintptr_t end = (uintptr_t(data) + bytes) & ~(page - 1);
    if (end <= begin) return;
    // MADV_HUGEPAGE was tried as well: slower here (page compaction).
    (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
}

}  // namespace kappa::io
