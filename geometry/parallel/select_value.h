// The k-th smallest of many non-negative floats, in parallel, without
// sorting or copying them: a radix select over their bit patterns (for
// non-negative IEEE floats, +inf included, the order of the bits as
// unsigned integers is the order of the values). One pass counts the values
// by their upper 16 bits, a second the values in the chosen bucket by their
// lower 16 bits. The counts are integers, so the answer is exactly
// std::nth_element's, whatever the thread count.
//
// Used where a median or percentile of a per-vertex or per-face quantity is
// taken for every view (feature size, colour-map ranges): on a 17.8M-face
// mesh a serial nth_element over a copied array was a serial step of each
// view.
#pragma once

#include "parallel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <vector>

namespace kappa {

namespace select_detail {

constexpr size_t kBuckets = 65536;

inline bool bits_of(float v, uint32_t& bits) {
    if (!(v >= 0.0f)) return false;  // NaN, negative: not counted
    v += 0.0f;                       // -0 -> +0
    std::memcpy(&bits, &v, sizeof bits);
    return true;
}

// Counts per bucket of the counted values, summed over ranges of indices.
// `bucket(bits, b)` says whether a value counts and in which bucket.
template <typename Value, typename Bucket>
std::vector<uint64_t> histogram(size_t n, Value& value, Bucket bucket) {
    std::vector<uint64_t> total(kBuckets, 0);
    std::mutex merge;
    const size_t min_chunk = std::max<size_t>(65536, n / 8 + 1);  // few ranges: each has kBuckets counters
    parallel_for_ranges(
        n,
        [&](size_t first, size_t last) {
            std::vector<uint32_t> count(kBuckets, 0);
            for (size_t i = first; i < last; ++i) {
                uint32_t bits, b;
                if (bits_of(value(i), bits) && bucket(bits, b)) ++count[b];
            }
            std::lock_guard<std::mutex> lock(merge);  // integer sums: the order does not matter
            for (size_t b = 0; b < kBuckets; ++b) total[b] += count[b];
        },
        min_chunk);
    return total;
}

}  // namespace select_detail

// Of the values value(i), i < n, that are >= 0 (NaN and negative ones are
// left out; there are m of them), the one with k_of(m) values below it in
// sorted order (k_of(m) < m), as std::nth_element would give. NaN when m == 0.
template <typename Value, typename RankOf>
float select_nonnegative(size_t n, Value value, RankOf k_of) {
    using namespace select_detail;
    const std::vector<uint64_t> upper =
        histogram(n, value, [](uint32_t bits, uint32_t& b) { return b = bits >> 16, true; });
    uint64_t m = 0;
    for (uint64_t c : upper) m += c;
    if (m == 0) return std::nanf("");
    uint64_t k = std::min<uint64_t>(uint64_t(k_of(size_t(m))), m - 1);
    uint32_t high = 0;
    while (k >= upper[high]) k -= upper[high++];
    const std::vector<uint64_t> lower = histogram(n, value, [high](uint32_t bits, uint32_t& b) {
        b = bits & 0xffffu;
        return (bits >> 16) == high;
    });
    uint32_t low = 0;
    while (k >= lower[low]) k -= lower[low++];
    const uint32_t bits = high << 16 | low;
    float out;
    std::memcpy(&out, &bits, sizeof out);
    return out;
}

}  // namespace kappa
