#include "ply_header.h"

#include "io_errors.h"

#include <charconv>
#include <cstring>
#include <string_view>

namespace kappa::io {

namespace {

struct TypeName {
    const char* name;
    PlyType type;
};
// The original names and the sized aliases (both are common in the wild).
constexpr TypeName kTypeNames[] = {
    {"char", PlyType::Int8},       {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},     {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16},   {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},     {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32},   {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64},
};

bool parse_type(std::string_view word, PlyType& type) {
    for (const TypeName& t : kTypeNames)
        if (word == t.name) {
            type = t.type;
            return true;
        }
    return false;
}

// Splits one header line into at most max_words blank-separated words.
std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

// Checks that the declared counts can fit in the bytes after the header, so
// that a corrupt count fails here instead of allocating terabytes.
void check_counts_fit(const PlyHeader& header, size_t remaining, const std::string& name) {
    const bool ascii = header.format == PlyFormat::Ascii;
    // ASCII: each value takes at least one character plus a separator.
    const uint64_t budget = ascii ? (uint64_t(remaining) + 1) / 2 : uint64_t(remaining);
    uint64_t needed = 0;
    for (const PlyElement& e : header.elements) {
        uint64_t item = e.min_item_size(header.format);
        if (item == 0) continue;  // no properties: nothing is stored per item
        if (e.count > (budget - needed) / item) {
            fail_load(name, "header declares " + std::to_string(e.count) + " " + quoted(e.name) +
                                " elements but only " + std::to_string(remaining) +
                                " bytes follow the header (file truncated or corrupt)");
        }
        needed += e.count * item;
    }
}

}  // namespace

size_t ply_type_size(PlyType type) {
    switch (type) {
        case PlyType::Int8:
        case PlyType::UInt8: return 1;
        case PlyType::Int16:
        case PlyType::UInt16: return 2;
        case PlyType::Int32:
        case PlyType::UInt32:
        case PlyType::Float32: return 4;
        case PlyType::Float64: return 8;
    }
    return 0;
}

bool ply_type_is_integer(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

const char* ply_type_name(PlyType type) {
    switch (type) {
        case PlyType::Int8: return "char";
        case PlyType::UInt8: return "uchar";
        case PlyType::Int16: return "short";
        case PlyType::UInt16: return "ushort";
        case PlyType::Int32: return "int";
        case PlyType::UInt32: return "uint";
        case PlyType::Float32: return "float";
        case PlyType::Float64: return "double";
    }
    return "?";
}

int PlyElement::find(const std::string& property_name) const {
    for (size_t i = 0; i < properties.size(); ++i)
        if (properties[i].name == property_name) return int(i);
    return -1;
}

size_t PlyElement::fixed_item_size() const {
    size_t size = 0;
    for (const PlyProperty& p : properties) {
        if (p.is_list) return 0;
        size += ply_type_size(p.type);
    }
    return size;
}

size_t PlyElement::min_item_size(PlyFormat format) const {
    if (format == PlyFormat::Ascii) return properties.size();
    size_t size = 0;
    for (const PlyProperty& p : properties) size += ply_type_size(p.is_list ? p.count_type : p.type);
    return size;
}

const PlyElement* PlyHeader::find(const std::string& element_name) const {
    for (const PlyElement& e : elements)
        if (e.name == element_name) return &e;
    return nullptr;
}

bool looks_like_ply(const char* data, size_t size) {
    return size >= 4 && std::memcmp(data, "ply", 3) == 0 && (data[3] == '\n' || data[3] == '\r');
}

PlyHeader parse_ply_header(const char* data, size_t size, const std::string& name) {
    if (!looks_like_ply(data, size)) fail_load(name, "not a PLY file (it does not start with 'ply')");

    PlyHeader header;
    bool have_format = false, have_end = false;
    size_t pos = 0, line_number = 0;
    while (pos < size && !have_end) {
        const char* nl = static_cast<const char*>(std::memchr(data + pos, '\n', size - pos));
        size_t line_end = nl ? size_t(nl - data) : size;
        std::string_view line(data + pos, line_end - pos);
        pos = nl ? line_end + 1 : size;
        ++line_number;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);

        auto words = split_words(line);
        auto bad_line = [&](const std::string& why) {
            fail_load(name, "header line " + std::to_string(line_number) + " " + quoted(line) + ": " + why);
        };
        if (line_number == 1 || words.empty()) continue;  // "ply" / blank line
        std::string_view key = words[0];
        if (key == "comment" || key == "obj_info") continue;
        if (key == "end_header") {
            have_end = true;
        } else if (key == "format") {
            if (words.size() < 2) bad_line("missing format name");
            if (words[1] == "ascii")
                header.format = PlyFormat::Ascii;
            else if (words[1] == "binary_little_endian")
                header.format = PlyFormat::BinaryLittleEndian;
            else if (words[1] == "binary_big_endian")
                header.format = PlyFormat::BinaryBigEndian;
            else
                bad_line("unknown format");
            have_format = true;
        } else if (key == "element") {
            if (words.size() != 3) bad_line("expected 'element NAME COUNT'");
            PlyElement e;
            e.name = std::string(words[1]);
            auto [ptr, ec] = std::from_chars(words[2].data(), words[2].data() + words[2].size(), e.count);
            if (ec != std::errc() || ptr != words[2].data() + words[2].size())
                bad_line("element count is not a non-negative integer");
            header.elements.push_back(std::move(e));
        } else if (key == "property") {
            if (header.elements.empty()) bad_line("property before any element");
            PlyProperty p;
            if (words.size() == 3) {
                if (!parse_type(words[1], p.type)) bad_line("unknown property type");
                p.name = std::string(words[2]);
            } else if (words.size() == 5 && words[1] == "list") {
                if (!parse_type(words[2], p.count_type) || !parse_type(words[3], p.type))
                    bad_line("unknown property type");
                if (!ply_type_is_integer(p.count_type)) bad_line("list count type must be an integer type");
                p.is_list = true;
                p.name = std::string(words[4]);
            } else {
                bad_line("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
            }
            header.elements.back().properties.push_back(std::move(p));
        } else {
            bad_line("unknown header keyword");
        }
    }
    if (!have_end) fail_load(name, "PLY header has no end_header line (truncated or not a PLY file)");
    if (!have_format) fail_load(name, "PLY header has no format line");
    header.body_offset = pos;
    check_counts_fit(header, size - pos, name);
    return header;
}

}  // namespace kappa::io
