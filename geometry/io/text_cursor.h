// Bounds-checked scanning of whitespace-separated ASCII tokens in a buffer
// that is not NUL-terminated (ASCII PLY, OFF, ASCII STL). Numbers are parsed
// with std::from_chars: locale-independent, no iostreams, exact rounding.
#pragma once

#include "geometry/io/float_chars.h"

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <system_error>
#include <type_traits>

namespace kappa::io {

class TextCursor {
public:
    TextCursor(const char* begin, const char* end) : begin_(begin), pos_(begin), end_(end) {}

    bool at_end() const { return pos_ >= end_; }
    const char* position() const { return pos_; }
    void set_position(const char* p) { pos_ = p; }  // back to an earlier position()
    size_t remaining() const { return size_t(end_ - pos_); }

    // Skips spaces, tabs, CR and LF.
    void skip_space() {
        while (pos_ < end_ && is_space(*pos_)) ++pos_;
    }
    // Skips spaces, tabs and CR but stops at LF.
    void skip_blank() {
        while (pos_ < end_ && is_blank(*pos_)) ++pos_;
    }
    // True at LF, at the end of the buffer, or (if comment != 0) at a comment.
    bool at_line_end(char comment = 0) const {
        return pos_ >= end_ || *pos_ == '\n' || (comment && *pos_ == comment);
    }
    // Moves just past the next LF (or to the end).
    void skip_line() {
        while (pos_ < end_ && *pos_ != '\n') ++pos_;
        if (pos_ < end_) ++pos_;
    }

    // The next token: skips whitespace (including line breaks), then takes
    // the run of non-space bytes. Empty at the end of the buffer.
    std::string_view token() {
        skip_space();
        return rest_of_token();
    }
    // Like token() but never crosses a line break: empty at the end of a line.
    std::string_view token_in_line() {
        skip_blank();
        return rest_of_token();
    }

    // 1-based line number of the current position (counts line breaks from
    // the start: for error messages only).
    size_t line_number() const {
        size_t line = 1;
        for (const char* p = begin_; p < pos_ && p < end_; ++p) line += (*p == '\n');
        return line;
    }

    static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
    static bool is_space(char c) { return c == '\n' || is_blank(c); }

private:
    std::string_view rest_of_token() {
        const char* start = pos_;
        while (pos_ < end_ && !is_space(*pos_)) ++pos_;
        return std::string_view(start, size_t(pos_ - start));
    }

    const char* begin_;
    const char* pos_;
    const char* end_;
};

// Parses a whole token as a number (a leading '+' is accepted; "inf" and
// "nan" parse, callers reject non-finite coordinates). False if the token is
// empty or has trailing junk. A floating-point value beyond the type's range
// becomes +-inf (overflow) or 0 / a subnormal (underflow), as with strtod.
template <typename T>
inline bool parse_number(std::string_view token, T& out) {
    const char* first = token.data();
    const char* last = first + token.size();
    if (first < last && *first == '+') {
        ++first;
        if (first < last && *first == '-') return false;
    }
    if (first == last) return false;
    auto [ptr, ec] = [&] {
        if constexpr (std::is_floating_point_v<T>) return float_from_chars(first, last, out);
        else return std::from_chars(first, last, out);
    }();
    if (ptr != last) return false;
    if (ec == std::errc()) return true;
    if constexpr (std::is_floating_point_v<T>) {
        if (ec == std::errc::result_out_of_range) {
            char buffer[128];
            size_t n = size_t(last - first);
            if (n >= sizeof buffer) return false;
            std::memcpy(buffer, first, n);
            buffer[n] = 0;
            if constexpr (std::is_same_v<T, float>)
                out = std::strtof(buffer, nullptr);
            else
                out = static_cast<T>(std::strtod(buffer, nullptr));
            return true;
        }
    }
    return false;
}

}  // namespace kappa::io
