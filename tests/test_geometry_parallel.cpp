// The parallel loops every pass is built on: each index once, whatever the
// thread count and the split.
#include "geometry/parallel/parallel.h"
#include "geometry/parallel/shift_down.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

using namespace kappa;

namespace {

// How many times each index of [0, n) was visited by `loop`.
template <typename Loop>
std::vector<int> visits(size_t n, const Loop& loop) {
    std::vector<std::atomic<int>> count(n);
    loop([&](size_t i) { ++count[i]; });
    std::vector<int> out(n);
    for (size_t i = 0; i < n; ++i) out[i] = count[i];
    return out;
}

}  // namespace

TEST_CASE("parallel loops visit every index exactly once", "[parallel]") {
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        set_thread_count(threads);
        for (size_t n : {size_t(0), size_t(1), size_t(7), size_t(4096), size_t(100003)}) {
            for (size_t chunk : {size_t(1), size_t(1000), size_t(16384), size_t(1) << 20}) {
                CAPTURE(threads, n, chunk);
                std::atomic<size_t> ranges_wrong{0};
                const auto counts = visits(n, [&](auto visit) {
                    parallel_for_chunks(
                        n,
                        [&](size_t b, size_t e) {
                            // Non-empty, in range, at most a chunk (one call for all with one thread).
                            ranges_wrong += b >= e || e > n || (threads > 1 && e - b > chunk);
                            for (size_t i = b; i < e; ++i) visit(i);
                        },
                        chunk);
                });
                CHECK(std::count(counts.begin(), counts.end(), 1) == std::ptrdiff_t(n));
                CHECK(ranges_wrong == 0);
            }
            const auto ranges = visits(n, [&](auto visit) {
                parallel_for_ranges(n, [&](size_t b, size_t e) {
                    for (size_t i = b; i < e; ++i) visit(i);
                });
            });
            CHECK(std::count(ranges.begin(), ranges.end(), 1) == std::ptrdiff_t(n));
            const auto chunked = visits(n, [&](auto visit) { parallel_for_chunked(n, visit, 100); });
            CHECK(std::count(chunked.begin(), chunked.end(), 1) == std::ptrdiff_t(n));
        }
    }
    set_thread_count(0);
}

TEST_CASE("shift_down moves a stretch as memmove does, whatever the thread count", "[parallel]") {
    // Long enough for several chunks (a chunk is 2^20 elements), and shifts of one, a few and more than a
    // chunk's worth of places; a stretch that ends in a chunk shorter than the shift too.
    const size_t n = (size_t(1) << 22) + 12345;
    for (unsigned threads : {1u, 2u, 5u}) {
        set_thread_count(threads);
        for (const size_t by : {size_t(1), size_t(7), size_t(1000), (size_t(1) << 20) + 3}) {
            for (const size_t end : {n, n - 5, size_t(3) << 20}) {
                INFO("threads " << threads << ", by " << by << ", end " << end);
                const size_t begin = by + 11;
                std::vector<uint32_t> data(n), expected(n);
                std::iota(data.begin(), data.end(), 0u);
                expected = data;
                std::memmove(expected.data() + begin - by, expected.data() + begin, (end - begin) * 4);
                shift_down(data.data(), begin, end, by);
                CHECK(data == expected);
            }
        }
    }
    set_thread_count(0);
}
