// glibc's heap tuned for kappa (app/heap_tuning.cpp): set up before main for
// every command; drawing commands also call keep_large_blocks().
#pragma once

namespace kappa::app {

// Blocks of any size come from the heap and stay there when freed, so the
// arrays each view of a drawing allocates reuse the last view's pages
// instead of faulting in fresh ones. The process keeps its peak memory.
void keep_large_blocks();

}  // namespace kappa::app
