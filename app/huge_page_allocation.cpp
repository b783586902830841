// Global operator new that asks the kernel for transparent huge pages on
// large blocks (Linux, THP in "madvise" mode as on Debian 12).
//
// Why: kappa's arrays for a 1M-face mesh are hundreds of MB, and each 4 KiB
// page costs a fault on first touch; on the machines we measured (VMs)
// that was ~3 ms per MB, more than the whole curvature computation.
// madvise(MADV_HUGEPAGE) makes those faults 2 MiB at a time (about 30x
// faster). Blocks come from malloc as usual, so delete is plain free().
#include <cstdint>
#include <cstdlib>
#include <new>

#include <sys/mman.h>

namespace {

constexpr size_t kHugePage = size_t(2) << 20;
constexpr size_t kLargeBlock = size_t(4) << 20;

void* allocate(size_t size) {
    if (size == 0) size = 1;
    void* p = std::malloc(size);
    if (!p) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    if (size >= kLargeBlock) {
        const uintptr_t begin = (uintptr_t(p) + kHugePage - 1) & ~(kHugePage - 1);
        const uintptr_t end = (uintptr_t(p) + size) & ~(kHugePage - 1);
        if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    }
#endif
    return p;
}

}  // namespace

void* operator new(size_t size) { return allocate(size); }
void* operator new[](size_t size) { return allocate(size); }
void* operator new(size_t size, const std::nothrow_t&) noexcept {
    try {
        return allocate(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t) noexcept { std::free(p); }
