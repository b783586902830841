#include "prefault.h"

#include "geometry/parallel/parallel.h"

#include <sys/mman.h>
#include <unistd.h>
#include <algorithm>
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
    // The kernel clears the pages of each thread's share in parallel, in
    // steps of 2 MiB.
    constexpr uintptr_t kStep = uintptr_t(2) << 20;
    const size_t steps = (end - begin + kStep - 1) / kStep;
    parallel_for_ranges(steps, [&](size_t first, size_t last) {
        const uintptr_t from = begin + first * kStep, to = std::min<uintptr_t>(end, begin + last * kStep);
        // MADV_HUGEPAGE was tried as well: slower here (page compaction).
        (void)madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
    }, 1);
}

}  // namespace kappa::io
