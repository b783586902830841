// Value readers for the body of a PLY file, one per encoding, with the same
// interface so that one generic element loop (ply_reader.cpp) serves both:
//   Status scalar(PlyType, double&)   any numeric value
//   Status integer(PlyType, int64_t&) an integer (floats only if integral)
//   Status skip(PlyType, uint64_t n)  n values of a type
//   uint64_t max_list_length(PlyType) an upper bound from the remaining data
#pragma once

#include "byte_order.h"
#include "ply_header.h"
#include "text_cursor.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace kappa::io {

enum class ReadStatus { Ok, EndOfData, BadValue };

// Converts a double to float without undefined behaviour: values beyond the
// float range become +-inf (rejected later as non-finite).
inline float to_float(double v) {
    if (v > 3.4028234663852886e38) return INFINITY;
    if (v < -3.4028234663852886e38) return -INFINITY;
    return static_cast<float>(v);
}

// An integral double in int64 range, or false.
inline bool double_to_int64(double v, int64_t& out) {
    if (!(v >= -9.2e18 && v <= 9.2e18) || v != std::floor(v)) return false;
    out = static_cast<int64_t>(v);
    return true;
}

class BinarySource {
public:
    BinarySource(const char* begin, const char* end, bool swap_bytes)
        : pos_(begin), end_(end), swap_(swap_bytes) {}

    const char* position() const { return pos_; }
    const char* end() const { return end_; }
    void set_position(const char* pos) { pos_ = pos; }  // after a fast path

    ReadStatus scalar(PlyType type, double& out) {
        if (size_t(end_ - pos_) < ply_type_size(type)) return ReadStatus::EndOfData;
        switch (type) {
            case PlyType::Int8: out = load<int8_t>(); break;
            case PlyType::UInt8: out = load<uint8_t>(); break;
            case PlyType::Int16: out = load<int16_t>(); break;
            case PlyType::UInt16: out = load<uint16_t>(); break;
            case PlyType::Int32: out = load<int32_t>(); break;
            case PlyType::UInt32: out = load<uint32_t>(); break;
            case PlyType::Float32: out = load<float>(); break;
            case PlyType::Float64: out = load<double>(); break;
        }
        return ReadStatus::Ok;
    }

    ReadStatus integer(PlyType type, int64_t& out) {
        if (size_t(end_ - pos_) < ply_type_size(type)) return ReadStatus::EndOfData;
        switch (type) {
            case PlyType::Int8: out = load<int8_t>(); return ReadStatus::Ok;
            case PlyType::UInt8: out = load<uint8_t>(); return ReadStatus::Ok;
            case PlyType::Int16: out = load<int16_t>(); return ReadStatus::Ok;
            case PlyType::UInt16: out = load<uint16_t>(); return ReadStatus::Ok;
            case PlyType::Int32: out = load<int32_t>(); return ReadStatus::Ok;
            case PlyType::UInt32: out = load<uint32_t>(); return ReadStatus::Ok;
            case PlyType::Float32: return float_to_integer(load<float>(), out);
            case PlyType::Float64: return float_to_integer(load<double>(), out);
        }
        return ReadStatus::BadValue;
    }

    // The value integer() last refused (for the message).
    double bad_value() const { return bad_value_; }

    ReadStatus skip(PlyType type, uint64_t n) {
        uint64_t size = ply_type_size(type);
        if (n > uint64_t(end_ - pos_) / size) return ReadStatus::EndOfData;
        pos_ += n * size;
        return ReadStatus::Ok;
    }

    uint64_t max_list_length(PlyType type) const { return uint64_t(end_ - pos_) / ply_type_size(type); }

private:
    ReadStatus float_to_integer(double v, int64_t& out) {
        if (double_to_int64(v, out)) return ReadStatus::Ok;
        bad_value_ = v;
        return ReadStatus::BadValue;
    }

    template <typename T>
    T load() {
        T value;
        std::memcpy(&value, pos_, sizeof(T));
        pos_ += sizeof(T);
        return swap_ ? byte_swapped(value) : value;
    }

    const char* pos_;
    const char* end_;
    bool swap_;
    double bad_value_ = 0;
};

// ASCII bodies are read as a stream of whitespace-separated tokens (line
// breaks are not significant, as in most PLY readers).
class AsciiSource {
public:
    // file_start: for line numbers in messages; reading starts at body.
    AsciiSource(const char* file_start, const char* body, const char* end) : cursor_(file_start, end) {
        cursor_.set_position(body);
    }

    const TextCursor& cursor() const { return cursor_; }
    std::string_view last_token() const { return last_; }

    ReadStatus scalar(PlyType type, double& out) {
        if (!next()) return ReadStatus::EndOfData;
        if (type == PlyType::Float32) {  // parse as float: exact float rounding
            float f;
            if (!parse_number(last_, f)) return ReadStatus::BadValue;
            out = f;
            return ReadStatus::Ok;
        }
        return parse_number(last_, out) ? ReadStatus::Ok : ReadStatus::BadValue;
    }

    ReadStatus integer(PlyType type, int64_t& out) {
        if (!next()) return ReadStatus::EndOfData;
        if (parse_number(last_, out)) return ReadStatus::Ok;
        double d;  // some writers print integers as "3.0"
        if (!ply_type_is_integer(type) || last_.find('.') != std::string_view::npos)
            if (parse_number(last_, d) && double_to_int64(d, out)) return ReadStatus::Ok;
        return ReadStatus::BadValue;
    }

    ReadStatus skip(PlyType, uint64_t n) {
        for (uint64_t i = 0; i < n; ++i)
            if (!next()) return ReadStatus::EndOfData;
        return ReadStatus::Ok;
    }

    // Each value takes at least one character and one separator.
    uint64_t max_list_length(PlyType) const { return (cursor_.remaining() + 1) / 2; }

private:
    bool next() {
        last_ = cursor_.token();
        return !last_.empty();
    }

    TextCursor cursor_;
    std::string_view last_;
};

}  // namespace kappa::io
