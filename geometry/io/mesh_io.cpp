#include "mesh_io.h"

#include "file_bytes.h"
#include "output_file.h"
#include "ply_header.h"

#include <algorithm>
#include <cctype>

namespace kappa {

namespace {

// OBJ has no magic: look for a statement such as "v 1 2 3" at the start of a
// line within the first few kilobytes.
bool looks_like_obj(const char* data, size_t size) {
    size_t limit = std::min<size_t>(size, 1 << 16);
    for (size_t i = 0; i + 2 < limit; ++i) {
        bool line_start = i == 0 || data[i - 1] == '\n';
        if (line_start && data[i] == 'v' && (data[i + 1] == ' ' || data[i + 1] == '\t')) return true;
    }
    return false;
}

}  // namespace

MeshFormat format_from_extension(const std::string& path) {
    const std::string ext = io::lower_extension(path);
    if (ext == "ply") return MeshFormat::Ply;
    if (ext == "obj") return MeshFormat::Obj;
    if (ext == "off") return MeshFormat::Off;
    if (ext == "stl") return MeshFormat::Stl;
    if (ext == "gltf" || ext == "glb") return MeshFormat::Gltf;
    return MeshFormat::Unknown;
}

MeshFormat format_from_content(const char* data, size_t size) {
    if (io::looks_like_ply(data, size)) return MeshFormat::Ply;
    if (io::looks_like_glb(data, size) || io::looks_like_gltf_json(data, size)) return MeshFormat::Gltf;
    if (io::looks_like_off(data, size)) return MeshFormat::Off;
    if (io::looks_like_binary_stl(data, size) || io::looks_like_ascii_stl(data, size)) return MeshFormat::Stl;
    if (looks_like_obj(data, size)) return MeshFormat::Obj;
    return MeshFormat::Unknown;
}

Mesh read_mesh(const char* data, size_t size, MeshFormat format, const std::string& name) {
    if (size == 0) io::fail_load(name, "file is empty");
    if (format == MeshFormat::Unknown) format = format_from_content(data, size);
    switch (format) {
        case MeshFormat::Ply: return read_ply(data, size, name);
        case MeshFormat::Obj: return read_obj(data, size, name);
        case MeshFormat::Off: return read_off(data, size, name);
        case MeshFormat::Stl: return read_stl(data, size, name);
        case MeshFormat::Gltf: return read_gltf(data, size, name);
        case MeshFormat::Unknown: break;
    }
    io::fail_load(name, "not a recognised mesh file (expected PLY, OBJ, OFF, STL or glTF)");
}

Mesh load_mesh(const std::string& path) {
    io::FileBytes bytes = io::read_file_bytes(path);
    return read_mesh(bytes.data.get(), bytes.size, format_from_extension(path), path);
}

}  // namespace kappa
