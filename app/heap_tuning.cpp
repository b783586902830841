// glibc's heap tuned for kappa's few, large, short-lived arrays (Linux,
// glibc).
//
// Why: on the machines we measured (VMs) every fresh page of memory costs a
// fault and a zeroing, 0.5 to 3 ms per MB: for a 1M-face mesh that was
// more than the curvature computation itself. So blocks up to 32 MiB come
// from the heap, never from a fresh mmap, and freed memory is kept: the
// temporaries of one stage reuse the pages of the previous one instead of
// faulting in new ones.
//
// Huge pages (madvise MADV_HUGEPAGE on large blocks) were used until
// 2026-11-25 and dropped: measured alternately with another program that
// had just freed its memory (trimesh2, as the README's comparison runs), a
// huge page fault cost so much more that `kappa curvature bunny-1M.ply` took
// 0.63 s instead of 0.40 s on one thread and 0.38 s instead of 0.33 s on two
// (medians of 12 rounds; an earlier 10 rounds: 0.48 against 0.37 s on one,
// 0.25 against 0.26 s on two), and `kappa render` 8% longer.
//
// Drawing (keep_large_blocks below) keeps the larger blocks too: each view's
// detail fields allocate and free the same arrays of hundreds of MB on a
// big mesh. On the 17.8M-face subdivided bunny at 1920x1080
// (bench_view_fields --views-only, 2 threads, process CPU time, loaded VM,
// 2026-11-27), heap instead of fresh mmaps took the curvature job from
// 7.7 to 5.6 s, the first view from 57.1 to 50.1 s and a new view from 23.4
// to 19.4 s, kernel time from 26 to 6 s, for 5% more peak memory (4.36 to
// 4.56 GB). `kappa curvature` does not: on bunny-1M it would keep 189 MB
// instead of 150 MB for 8% less CPU time.
#include "heap_tuning.h"

#include "geometry/io/prefault.h"

#include <malloc.h>

#include <cstdlib>

namespace {

struct HeapTuning {
    HeapTuning() {
        mallopt(M_MMAP_THRESHOLD, 32 << 20);  // the largest value glibc accepts
        mallopt(M_TRIM_THRESHOLD, 1 << 30);   // keep freed memory for reuse
        mallopt(M_TOP_PAD, 16 << 20);         // grow the heap in big steps
    }
} heap_tuning;

}  // namespace

namespace kappa::app {

void keep_large_blocks() {
    mallopt(M_MMAP_MAX, 0);  // no block from mmap: every freed block stays for reuse
}

HeapBlock::HeapBlock(size_t bytes) : data_(std::malloc(bytes)), bytes_(data_ ? bytes : 0) {
    // Not even the top of the heap goes back (mallopt: -1 turns trimming off), or freeing a block
    // over the trim threshold would give its pages back at once.
    mallopt(M_TRIM_THRESHOLD, -1);
}

HeapBlock::~HeapBlock() { std::free(data_); }

void HeapBlock::fault_in() {
    if (data_) io::prefault(data_, bytes_);
}

}  // namespace kappa::app
