// app/heap_tuning.h: a HeapBlock taken on one thread and faulted in on another
// leaves its memory, once freed, to the first thread's next allocations, in
// memory (mincore): even a block over the trim threshold the process starts
// with (1 GiB), which glibc would otherwise give back to the system.
#include <catch2/catch.hpp>

#include "app/heap_tuning.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <thread>
#include <vector>

namespace {

// The fraction of [p, p + bytes)'s whole pages that are in memory.
double resident_fraction(const void* p, size_t bytes) {
    const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
    const uintptr_t begin = (uintptr_t(p) + page - 1) & ~(page - 1), end = (uintptr_t(p) + bytes) & ~(page - 1);
    std::vector<unsigned char> in((end - begin) / page);
    REQUIRE(mincore(reinterpret_cast<void*>(begin), end - begin, in.data()) == 0);
    size_t resident = 0;
    for (unsigned char c : in) resident += c & 1;
    return double(resident) / double(in.size());
}

}  // namespace

TEST_CASE("HeapBlock: faulted in on another thread, the next block of that size is in memory before it is touched",
          "[heap]") {
    kappa::app::keep_large_blocks();  // as kappa view: every block from the heap
    const size_t bytes = size_t(1088) << 20;  // over the 1 GiB trim threshold
    // Not warmed, a block this big is fresh heap, not in memory until touched (the check can tell).
    void* cold = std::malloc(bytes);
    REQUIRE(cold);
    CHECK(resident_fraction(cold, bytes) < 0.05);
    std::free(cold);
    {
        kappa::app::HeapBlock block(bytes);  // as the viewer's window thread
        std::thread([&] { block.fault_in(); }).join();  // as its worker
    }
    void* warm = std::malloc(bytes);
    REQUIRE(warm);
    CHECK(resident_fraction(warm, bytes) > 0.99);
    std::free(warm);
}
