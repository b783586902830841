// Big buffers are filled faster when their pages are mapped up front: on
// some machines (notably VMs) a first-touch page fault costs several
// microseconds, which for a 23 MB mesh file outweighs the parsing itself.
#pragma once

#include <cstddef>
#include <vector>

namespace kappa::io {

// Asks the kernel to back [data, data + bytes) with pages now, in one call
// (madvise MADV_POPULATE_WRITE, Linux 5.14+), shared among the worker
// threads (parallel.h). Contents are unchanged. A hint only: skipped for
// small ranges, ignored where unsupported.
void prefault(void* data, size_t bytes);

// reserve(n) followed by prefault() of the reserved storage.
template <typename T>
void reserve_prefaulted(std::vector<T>& v, size_t n) {
    if (v.capacity() >= n) return;
    v.reserve(n);
    prefault(v.data(), v.capacity() * sizeof(T));
}

}  // namespace kappa::io
