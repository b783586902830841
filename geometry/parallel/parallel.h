// Deterministic data-parallel loops. Work is split into contiguous ranges;
// each index is computed by exactly one thread and writes only its own
// outputs, so results never depend on the thread count.
#pragma once

#include <cstddef>
#include <functional>

namespace kappa {

// Number of worker threads used by parallel_for (default: hardware
// concurrency, at least 1). Setting 0 restores the default.
void set_thread_count(unsigned n);
unsigned thread_count();

// Calls body(begin, end) on disjoint ranges covering [0, n). Small n runs
// inline on the calling thread.
void parallel_for_ranges(size_t n, const std::function<void(size_t, size_t)>& body,
                         size_t min_chunk = 4096);

// Calls body(begin, end) on consecutive chunks of about `chunk` indices
// covering [0, n), handed to whichever worker is free: a pass whose
// threads would otherwise wait for the slowest of fixed halves (a core
// the VM lends elsewhere for a moment, a range of costlier items) keeps
// them all busy to the end. As parallel_for_ranges, each index is
// computed by one thread writing only its own outputs, so results never
// depend on the thread count; bodies must not assume one range a thread.
// With one worker (or one chunk), a single call for all of [0, n).
void parallel_for_chunks(size_t n, const std::function<void(size_t, size_t)>& body, size_t chunk = 16384);

// Calls body(i) for every i in [0, n).
template <typename Body>
void parallel_for(size_t n, Body&& body, size_t min_chunk = 4096) {
    parallel_for_ranges(
        n, [&](size_t b, size_t e) { for (size_t i = b; i < e; ++i) body(i); }, min_chunk);
}

// Calls body(i) for every i in [0, n), over parallel_for_chunks.
template <typename Body>
void parallel_for_chunked(size_t n, Body&& body, size_t chunk = 16384) {
    parallel_for_chunks(
        n, [&](size_t b, size_t e) { for (size_t i = b; i < e; ++i) body(i); }, chunk);
}

// Calls body(i) for every i in [0, n), handing out one index at a time to
// whichever worker is free: for items of very unequal cost. Each item must
// write only its own outputs (then results never depend on the thread count).
void parallel_for_dynamic(size_t n, const std::function<void(size_t)>& body);

}  // namespace kappa
