// Host byte order and byte swapping for binary formats.
#pragma once

#include <cstring>
#include <utility>

namespace kappa::io {

constexpr bool kHostLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

// Reverses the bytes of a value of sizeof(T) bytes.
template <typename T>
T byte_swapped(T value) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    std::memcpy(&value, b, sizeof(T));
    return value;
}

// Reads a little-endian value from unaligned memory.
template <typename T>
T load_little_endian(const char* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));
    return kHostLittleEndian ? value : byte_swapped(value);
}

}  // namespace kappa::io
