// std::from_chars and std::to_chars for floating point, where the standard
// library has them (libstdc++, the desktop build). The libc++ of Debian's
// emscripten (the browser build, web/) has only the integer ones: there the C
// library's strtod/strtof and snprintf stand in, on the same syntax (no '+',
// no leading spaces, no hexadecimal: the text is cut before any other
// character, as from_chars stops there) and with the same correct rounding.
#pragma once

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <type_traits>

namespace kappa::io {

template <typename T>
std::from_chars_result float_from_chars(const char* first, const char* last, T& value) {
    static_assert(std::is_floating_point_v<T>);
#if !defined(_LIBCPP_VERSION)
    return std::from_chars(first, last, value);
#else
    if (first == last || *first == '+') return {first, std::errc::invalid_argument};
    std::string text(first, last);
    const size_t end_of_number = text.find_first_not_of("0123456789+-.eEinfatyINFATY");
    if (end_of_number != std::string::npos) text.resize(end_of_number);
    if (text.empty()) return {first, std::errc::invalid_argument};
    errno = 0;
    char* end = nullptr;
    const T v = std::is_same_v<T, float> ? T(std::strtof(text.c_str(), &end)) : T(std::strtod(text.c_str(), &end));
    if (end == text.c_str()) return {first, std::errc::invalid_argument};
    const char* ptr = first + (end - text.c_str());
    if (errno == ERANGE) return {ptr, std::errc::result_out_of_range};  // value left as it was, as from_chars
    value = v;
    return {ptr, std::errc()};
#endif
}

// The shortest text that reads back to `value`.
inline char* float_to_chars(char* first, char* last, float value) {
#if !defined(_LIBCPP_VERSION)
    return std::to_chars(first, last, value).ptr;
#else
    int n = 0;
    for (int digits = 1; digits <= 9; ++digits) {
        n = std::snprintf(first, size_t(last - first), "%.*g", digits, double(value));
        if (std::strtof(first, nullptr) == value) break;
    }
    return first + n;
#endif
}

// printf's "%.*g" with this precision.
inline char* float_to_chars(char* first, char* last, float value, int precision) {
#if !defined(_LIBCPP_VERSION)
    return std::to_chars(first, last, value, std::chars_format::general, precision).ptr;
#else
    return first + std::snprintf(first, size_t(last - first), "%.*g", precision, double(value));
#endif
}

}  // namespace kappa::io
