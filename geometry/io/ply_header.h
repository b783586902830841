// The PLY header (Turk 1994; http://paulbourke.net/dataformats/ply/):
//   ply
//   format ascii|binary_little_endian|binary_big_endian 1.0
//   comment ... / obj_info ...
//   element NAME COUNT
//   property TYPE NAME                       (scalar)
//   property list COUNT_TYPE ITEM_TYPE NAME  (variable-length list)
//   end_header
// TYPE is char uchar short ushort int uint float double or one of the sized
// aliases int8 uint8 int16 uint16 int32 uint32 float32 float64.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace kappa::io {

enum class PlyType : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class PlyFormat : uint8_t { Ascii, BinaryLittleEndian, BinaryBigEndian };

size_t ply_type_size(PlyType type);
bool ply_type_is_integer(PlyType type);
const char* ply_type_name(PlyType type);  // canonical name: "uchar", "float", ...

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;  // scalar type, or type of the list items
    bool is_list = false;
    PlyType count_type = PlyType::UInt8;  // lists only
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;

    // Index of the property with this name, or -1.
    int find(const std::string& property_name) const;
    // Bytes of one item in binary files if every property is a scalar, else 0.
    size_t fixed_item_size() const;
    // Smallest possible size of one item: in bytes for binary files, in
    // tokens for ASCII files (lists count as their length field only).
    size_t min_item_size(PlyFormat format) const;
};

struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
    size_t body_offset = 0;  // first byte after the end_header line

    // First element with this name, or nullptr.
    const PlyElement* find(const std::string& element_name) const;
};

// True if the data starts with the PLY magic line.
bool looks_like_ply(const char* data, size_t size);

// Parses and checks the header; element counts are checked against the size
// of the rest of the file so that no count can trigger a huge allocation.
// Throws MeshLoadError "NAME: problem".
PlyHeader parse_ply_header(const char* data, size_t size, const std::string& name);

}  // namespace kappa::io
