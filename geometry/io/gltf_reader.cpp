#include "gltf_io.h"

#include "vertex_weld.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <utility>

#include <sys/stat.h>

namespace kappa {

namespace io {

bool looks_like_glb(const char* data, size_t size) { return size >= 12 && std::memcmp(data, "glTF", 4) == 0; }

bool looks_like_gltf_json(const char* data, size_t size) {
    size_t i = 0;
    while (i < size && std::isspace(static_cast<unsigned char>(data[i]))) ++i;
    if (i >= size || data[i] != '{') return false;
    const std::string head(data, std::min<size_t>(size, 1 << 16));
    return head.find("\"asset\"") != std::string::npos;
}

}  // namespace io

namespace {

// A tinygltf accessor's bytes, bounds-checked: element i starts at at(i).
struct AccessorView {
    const unsigned char* base = nullptr;
    size_t count = 0, stride = 0;
    const unsigned char* at(size_t i) const { return base + i * stride; }
};

AccessorView view_of(const tinygltf::Model& model, int index, size_t element_size, const std::string& name,
                     const char* what) {
    if (index < 0 || size_t(index) >= model.accessors.size()) io::fail_load(name, std::string(what) + ": no such accessor");
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    if (a.sparse.isSparse) io::fail_load(name, std::string(what) + ": sparse accessors are not supported");
    AccessorView v;
    v.count = a.count;
    if (a.count == 0) return v;
    if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size())
        io::fail_load(name, std::string(what) + ": accessor without data");
    const tinygltf::BufferView& bv = model.bufferViews[size_t(a.bufferView)];
    if (bv.buffer < 0 || size_t(bv.buffer) >= model.buffers.size())
        io::fail_load(name, std::string(what) + ": buffer view without buffer");
    const std::vector<unsigned char>& data = model.buffers[size_t(bv.buffer)].data;
    v.stride = bv.byteStride ? bv.byteStride : element_size;
    // The last element must end inside both the buffer view and the buffer.
    // Counts and offsets are any 64-bit values in the file: every sum and
    // product is checked, so that none can wrap round into the buffer.
    size_t span = 0, begin = 0, end = 0;  // span: the accessor's bytes
    const bool inside = v.stride >= element_size && !__builtin_mul_overflow(a.count - 1, v.stride, &span) &&
                        !__builtin_add_overflow(span, element_size, &span) && a.byteOffset <= bv.byteLength &&
                        span <= bv.byteLength - a.byteOffset &&
                        !__builtin_add_overflow(bv.byteOffset, a.byteOffset, &begin) &&
                        !__builtin_add_overflow(begin, span, &end) && end <= data.size();
    if (!inside)
        io::fail_load(name, std::string(what) + ": accessor of " + std::to_string(a.count) +
                                " elements reaches outside its buffer");
    v.base = data.data() + begin;
    return v;
}

glm::mat4 local_transform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::dmat4 m;
        for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = node.matrix[size_t(i)];  // column-major, as glTF
        return glm::mat4(m);
    }
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3)
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)  // glTF quaternions are (x, y, z, w)
        m = m * glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return glm::mat4(m);
}

// Appends the triangle corners of one primitive, transformed.
void add_primitive(const tinygltf::Model& model, const tinygltf::Primitive& prim, const glm::mat4& transform,
                   std::vector<glm::vec3>& corners, const std::string& name) {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
        return;  // points and lines
    const auto pos = prim.attributes.find("POSITION");
    if (pos == prim.attributes.end()) io::fail_load(name, "a triangle primitive has no POSITION");
    if (pos->second < 0 || size_t(pos->second) >= model.accessors.size())
        io::fail_load(name, "POSITION: no such accessor");
    const tinygltf::Accessor& pa = model.accessors[size_t(pos->second)];
    if (pa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || pa.type != TINYGLTF_TYPE_VEC3)
        io::fail_load(name, "POSITION must be float VEC3");
    const AccessorView positions = view_of(model, pos->second, 12, name, "POSITION");
    std::vector<glm::vec3> p(positions.count);
    for (size_t i = 0; i < p.size(); ++i) {
        float xyz[3];
        std::memcpy(xyz, positions.at(i), sizeof xyz);
        p[i] = glm::vec3(transform * glm::vec4(xyz[0], xyz[1], xyz[2], 1.0f));
        if (!std::isfinite(p[i].x) || !std::isfinite(p[i].y) || !std::isfinite(p[i].z))
            io::fail_load(name, "glTF: a position is not finite (after the node transforms)");
    }

    std::vector<uint32_t> index;
    if (prim.indices >= 0) {
        if (size_t(prim.indices) >= model.accessors.size()) io::fail_load(name, "indices: no such accessor");
        const tinygltf::Accessor& ia = model.accessors[size_t(prim.indices)];
        size_t size = 0;
        switch (ia.componentType) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: size = 1; break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: size = 2; break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: size = 4; break;
            default: io::fail_load(name, "indices must be unsigned byte, short or int");
        }
        if (ia.type != TINYGLTF_TYPE_SCALAR) io::fail_load(name, "indices must be scalars");
        const AccessorView iv = view_of(model, prim.indices, size, name, "indices");
        index.resize(iv.count);
        for (size_t i = 0; i < iv.count; ++i) {
            uint32_t k = 0;
            if (size == 1) k = *iv.at(i);
            else if (size == 2) { uint16_t s; std::memcpy(&s, iv.at(i), 2); k = s; }
            else std::memcpy(&k, iv.at(i), 4);
            if (k >= p.size())
                io::fail_load(name, "index " + std::to_string(k) + " out of range (POSITION has " +
                                        std::to_string(p.size()) + " vertices)");
            index[i] = k;
        }
    } else {
        index.resize(p.size());
        for (size_t i = 0; i < index.size(); ++i) index[i] = uint32_t(i);
    }

    // glTF 2.0, 3.7.2.1: a global transform with a negative determinant (a
    // mirror) makes the primitive's front faces clockwise; reversing each
    // triangle turns them back to counter-clockwise, so normals stay outward.
    const bool mirrored = glm::determinant(glm::mat3(transform)) < 0.0f;
    auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (mirrored) std::swap(b, c);
        corners.insert(corners.end(), {p[a], p[b], p[c]});
    };
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        for (size_t i = 0; i + 2 < index.size(); i += 3) triangle(index[i], index[i + 1], index[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {  // every other triangle flips its order
        for (size_t i = 0; i + 2 < index.size(); ++i)
            i % 2 ? triangle(index[i + 1], index[i], index[i + 2]) : triangle(index[i], index[i + 1], index[i + 2]);
    } else {  // fan around the first index
        for (size_t i = 1; i + 1 < index.size(); ++i) triangle(index[0], index[i], index[i + 1]);
    }
}

bool no_images(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;  // kappa reads geometry only
}

// External buffers: regular files only, read whole, no shell-style path
// expansion (tinygltf's default expands "~" and "$VAR" with wordexp).
bool regular_file(const std::string& path, void*) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::string path_as_is(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* error, const std::string& path, void*) {
    struct stat st {};
    if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {
        if (error) *error += "cannot read buffer file '" + path + "'";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(size_t(st.st_size));
    if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(out->size()))) {
        if (error) *error += "cannot read buffer file '" + path + "'";
        return false;
    }
    return true;
}

bool no_writes(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
    if (error) *error += "kappa does not write glTF";
    return false;
}

}  // namespace

Mesh read_gltf(const char* data, size_t size, const std::string& name) {
    // tinygltf takes the size as a 32-bit unsigned: a larger one would be cut.
    if (size > std::numeric_limits<unsigned>::max())
        io::fail_load(name, "glTF: the file has " + std::to_string(size) +
                                " bytes, more than tinygltf can read (4 GiB - 1)");
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(no_images, nullptr);
    loader.SetFsCallbacks({regular_file, path_as_is, read_whole_file, no_writes, nullptr});
    tinygltf::Model model;
    std::string error, warning;
    const auto slash = name.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : name.substr(0, slash);
    const bool binary = io::looks_like_glb(data, size);
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                                  reinterpret_cast<const unsigned char*>(data), unsigned(size),
                                                  folder)
                    : loader.LoadASCIIFromString(&model, &error, &warning, data, unsigned(size), folder);
    } catch (const std::exception& e) {
        // tinygltf can throw on malformed input (e.g. a .glb whose only buffer
        // has byteLength 0 beside a BIN chunk: std::out_of_range from inside).
        error = std::string("malformed file (") + e.what() + ")";
    }
    if (!ok) {
        std::string first = error.substr(0, error.find('\n'));
        if (first.empty()) first = "not a valid glTF 2.0 file";
        io::fail_load(name, "glTF: " + io::quoted(first, 120));
    }

    std::vector<glm::vec3> corners;
    std::vector<int> on_path;  // cycle guard: nodes on the current path
    std::function<void(int, const glm::mat4&)> visit = [&](int n, const glm::mat4& parent) {
        if (n < 0 || size_t(n) >= model.nodes.size()) io::fail_load(name, "glTF: no such node " + std::to_string(n));
        if (std::find(on_path.begin(), on_path.end(), n) != on_path.end()) io::fail_load(name, "glTF: nodes form a cycle");
        const tinygltf::Node& node = model.nodes[size_t(n)];
        const glm::mat4 transform = parent * local_transform(node);
        if (node.mesh >= 0) {
            if (size_t(node.mesh) >= model.meshes.size()) io::fail_load(name, "glTF: no such mesh");
            for (const auto& prim : model.meshes[size_t(node.mesh)].primitives)
                add_primitive(model, prim, transform, corners, name);
        }
        on_path.push_back(n);
        for (int child : node.children) visit(child, transform);
        on_path.pop_back();
    };
    if (!model.scenes.empty()) {
        const int scene = model.defaultScene >= 0 && size_t(model.defaultScene) < model.scenes.size() ? model.defaultScene : 0;
        for (int n : model.scenes[size_t(scene)].nodes) visit(n, glm::mat4(1.0f));
    } else {
        for (const auto& mesh : model.meshes)
            for (const auto& prim : mesh.primitives) add_primitive(model, prim, glm::mat4(1.0f), corners, name);
    }
    if (corners.empty()) io::fail_load(name, "glTF: no triangles in the scene");
    return io::weld_exact(corners);
}

}  // namespace kappa
