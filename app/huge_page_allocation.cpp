// Global operator new tuned for kappa's few, large, short-lived arrays
// (Linux, glibc; transparent huge pages in "madvise" mode as on Debian 12).
//
// Why: on the machines we measured (VMs) every fresh page of memory costs a
// fault and a zeroing, ~3 ms per MB in 4 KiB pages and still ~1 ms per MB in
// huge pages: for a 1M-face mesh that was more than the curvature
// computation itself. So:
//  - blocks up to 32 MiB come from the heap, never from a fresh mmap, and
//    freed memory is kept: the temporaries of one stage reuse the pages of
//    the previous one instead of faulting in new ones;
//  - large blocks ask for huge pages (madvise MADV_HUGEPAGE), which fault
//    2 MiB at a time.
// Blocks come from malloc as usual, so delete is plain free().
#include <malloc.h>
#include <sys/mman.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr size_t kHugePage = size_t(2) << 20;
constexpr size_t kLargeBlock = size_t(4) << 20;

struct HeapTuning {
    HeapTuning() {
        mallopt(M_MMAP_THRESHOLD, 32 << 20);  // the largest value glibc accepts
        mallopt(M_TRIM_THRESHOLD, 1 << 30);   // keep freed memory for reuse
        mallopt(M_TOP_PAD, 16 << 20);         // grow the heap in big steps
    }
} heap_tuning;

void advise_huge_pages(void* p, size_t size) {
#ifdef MADV_HUGEPAGE
    if (size >= kLargeBlock) {
        const uintptr_t begin = (uintptr_t(p) + kHugePage - 1) & ~(kHugePage - 1);
        const uintptr_t end = (uintptr_t(p) + size) & ~(kHugePage - 1);
        if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    }
#endif
}

void* allocate(size_t size) {
    if (size == 0) size = 1;
    void* p = std::malloc(size);
    if (!p) throw std::bad_alloc();
    advise_huge_pages(p, size);
    return p;
}

// Over-aligned types (a cache line a record) take the same path.
void* allocate(size_t size, std::align_val_t alignment) {
    if (size == 0) size = 1;
    void* p = nullptr;
    if (posix_memalign(&p, std::max(size_t(alignment), sizeof(void*)), size) != 0) throw std::bad_alloc();
    advise_huge_pages(p, size);
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

void* operator new(size_t size, std::align_val_t a) { return allocate(size, a); }
void* operator new[](size_t size, std::align_val_t a) { return allocate(size, a); }
void* operator new(size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
    try {
        return allocate(size, a);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](size_t size, std::align_val_t a, const std::nothrow_t& tag) noexcept {
    return operator new(size, a, tag);
}
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t, std::align_val_t) noexcept { std::free(p); }
