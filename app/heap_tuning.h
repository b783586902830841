// glibc's heap tuned for kappa (app/heap_tuning.cpp): set up before main for
// every command; drawing commands also call keep_large_blocks().
#pragma once

#include <cstddef>

namespace kappa::app {

// Blocks of any size come from the heap and stay there when freed, so the
// arrays each view of a drawing allocates reuse the last view's pages
// instead of faulting in fresh ones. The process keeps its peak memory.
void keep_large_blocks();

// After keep_large_blocks: a block of the heap taken by one thread, its
// pages faulted in by another (fault_in, with the worker threads), then
// freed, for the first thread's next allocations to reuse; freed memory is
// no longer given back to the system. A software GL (Mesa's llvmpipe) makes
// its buffers in host memory and touches every page, and on the VMs we
// measured a page touched for the first time costs up to 5 ms a MB once the
// process holds several GB: the viewer's worker takes that cost for a big
// first view's buffers instead of the window's thread. The block must come
// from the window thread: glibc gives a thread of its own a block this big
// from a mapping of its own (whatever M_MMAP_MAX says), unmapped when freed.
class HeapBlock {
public:
    explicit HeapBlock(size_t bytes);
    ~HeapBlock();  // frees the block, on whichever thread lets go of it last
    HeapBlock(const HeapBlock&) = delete;
    HeapBlock& operator=(const HeapBlock&) = delete;
    void fault_in();

private:
    void* data_;
    size_t bytes_;
};

}  // namespace kappa::app
