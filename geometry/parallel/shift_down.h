// Moves a long stretch of an array a few places down, in parallel: what
// std::memmove(data + begin - by, data + begin, (end - begin) * sizeof(T))
// does, on every thread (the vertex-face rows of a big mesh are hundreds of
// MB, and a split moves all of them past the first vertex that loses
// corners: split_at_creases, creases.cpp).
#pragma once

#include "parallel.h"

#include <algorithm>
#include <cstring>
#include <type_traits>
#include <vector>

namespace kappa {

// [begin, end) to [begin - by, end - by); by <= begin. Each chunk of the stretch first moves within
// itself (all but its first `by` elements, saved beforehand), then the saved heads go just below their
// chunks, over what the chunk below left behind.
template <typename T> void shift_down(T* data, size_t begin, size_t end, size_t by) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (by == 0 || begin >= end) return;
    constexpr size_t kChunk = size_t(1) << 20;  // elements
    const size_t length = end - begin, chunk = std::max(kChunk, by);
    const size_t chunks = (length + chunk - 1) / chunk;
    if (chunks == 1) {
        std::memmove(data + begin - by, data + begin, length * sizeof(T));
        return;
    }
    std::vector<T> heads(chunks * by);
    auto first_of = [&](size_t c) { return begin + c * chunk; };
    auto end_of = [&](size_t c) { return std::min(end, first_of(c) + chunk); };
    parallel_for_chunked(chunks, [&](size_t c) {
        const size_t first = first_of(c), last = end_of(c), head = std::min(by, last - first);
        std::memcpy(heads.data() + c * by, data + first, head * sizeof(T));
        std::memmove(data + first, data + first + head, (last - first - head) * sizeof(T));
    }, 1);
    // Chunk c now holds its elements from `head` on at [first, last - head): its head goes to [first - by, ...),
    // the last `by` places of the chunk below (or below the stretch), which hold nothing still needed.
    for (size_t c = 0; c < chunks; ++c) {
        const size_t first = first_of(c), head = std::min(by, end_of(c) - first);
        std::memcpy(data + first - by, heads.data() + c * by, head * sizeof(T));
    }
}

}  // namespace kappa
