// PLY body reading. One generic loop reads any element layout in either
// encoding; two fast paths cover the common binary layout in the host byte
// order (vertex = fixed-size record with float x, y, z; face = uchar count +
// int indices), reading at memory speed.
#include "ply_io.h"

#include "mesh_assembly.h"
#include "ply_header.h"
#include "ply_sources.h"
#include "prefault.h"

#include "geometry/parallel/parallel.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <limits>

namespace kappa {
namespace io {
namespace {

// The parts of one element the reader keeps; everything else is skipped.
struct ElementPlan {
    enum class Kind { Skip, Vertices, Faces, Strips } kind = Kind::Skip;
    int coord[3] = {-1, -1, -1};  // property indices of x, y, z (vertices)
    int index_list = -1;          // property index of the vertex index list

    // 0, 1, 2 if property k is x, y or z, else -1.
    int axis_of(size_t k) const {
        for (int a = 0; a < 3; ++a)
            if (coord[a] == int(k)) return a;
        return -1;
    }
};

struct ReadContext {
    const std::string& name;
    const PlyElement* element = nullptr;
    uint64_t item = 0;
    size_t vertex_count = 0;
};

// list_length: the length of a list that does not fit in the rest of the
// file, as written (named in the message), or -1.
[[noreturn]] void fail_truncated(const ReadContext& ctx, int64_t list_length = -1) {
    fail_load(ctx.name, "unexpected end of file in element " + quoted(ctx.element->name) + " (item " +
                            std::to_string(ctx.item) + " of " + std::to_string(ctx.element->count) +
                            (list_length >= 0 ? ", a list of " + std::to_string(list_length) + " values" : "") +
                            "): the file is truncated or its counts are wrong");
}

[[noreturn]] void fail_bad_value(const ReadContext& ctx, const std::string& what) {
    fail_load(ctx.name,
              what + " in element " + quoted(ctx.element->name) + " (item " + std::to_string(ctx.item) + ")");
}

// Turns a failed read into the error message of its encoding.
void check(ReadStatus status, const ReadContext& ctx, const BinarySource& source) {
    if (status == ReadStatus::EndOfData) fail_truncated(ctx);
    if (status == ReadStatus::BadValue) {
        char value[32];
        std::snprintf(value, sizeof value, "%.17g", source.bad_value());
        fail_bad_value(ctx, std::string("value ") + value +
                                " where an integer is required (not an integer, or beyond 64 bits)");
    }
}

void check(ReadStatus status, const ReadContext& ctx, const AsciiSource& source) {
    if (status == ReadStatus::EndOfData) fail_truncated(ctx);
    if (status == ReadStatus::BadValue)
        fail_bad_value(ctx, "bad number " + quoted(source.last_token()) + " on line " +
                                std::to_string(source.cursor().line_number()));
}

// Reads every item of an element, calling on_item(xyz, list, list_size) with
// the coordinates and the index list named in the plan.
template <typename Source, typename OnItem>
void read_element(Source& source, const ElementPlan& plan, ReadContext& ctx, OnItem&& on_item) {
    const PlyElement& element = *ctx.element;
    if (element.properties.empty()) return;  // nothing stored per item
    double xyz[3] = {0, 0, 0};
    std::vector<int64_t> list;
    for (ctx.item = 0; ctx.item < element.count; ++ctx.item) {
        for (size_t k = 0; k < element.properties.size(); ++k) {
            const PlyProperty& p = element.properties[k];
            if (!p.is_list) {
                int axis = plan.axis_of(k);
                if (axis >= 0)
                    check(source.scalar(p.type, xyz[axis]), ctx, source);
                else
                    check(source.skip(p.type, 1), ctx, source);
                continue;
            }
            int64_t n = 0;
            check(source.integer(p.count_type, n), ctx, source);
            if (n < 0) fail_bad_value(ctx, "negative list length " + std::to_string(n));
            if (uint64_t(n) > source.max_list_length(p.type)) fail_truncated(ctx, n);
            if (int(k) != plan.index_list) {
                check(source.skip(p.type, uint64_t(n)), ctx, source);
                continue;
            }
            list.resize(size_t(n));
            for (int64_t j = 0; j < n; ++j) check(source.integer(p.type, list[size_t(j)]), ctx, source);
        }
        on_item(xyz, list.data(), list.size());
    }
}

// Fast path: fixed-size vertex records with float x, y, z in host order.
bool read_vertices_fast(const char*& pos, const char* end, const PlyElement& element, const ElementPlan& plan,
                        ReadContext& ctx, std::vector<glm::vec3>& out) {
    size_t stride = element.fixed_item_size();
    if (stride == 0) return false;
    size_t offset[3];
    for (int a = 0; a < 3; ++a) {
        if (element.properties[size_t(plan.coord[a])].type != PlyType::Float32) return false;
        offset[a] = 0;
        for (int k = 0; k < plan.coord[a]; ++k)
            offset[a] += ply_type_size(element.properties[size_t(k)].type);
    }
    if (element.count > uint64_t(end - pos) / stride) {
        ctx.item = uint64_t(end - pos) / stride;
        fail_truncated(ctx);
    }
    size_t n = size_t(element.count);
    reserve_prefaulted(out, positions_room(n));
    out.resize(n);
    if (n == 0) {
        // nothing to copy (and memcpy must not see the null data())
    } else if (stride == 12 && offset[0] == 0 && offset[1] == 4 && offset[2] == 8) {
        std::memcpy(static_cast<void*>(out.data()), pos, n * 12);
    } else {
        for (size_t i = 0; i < n; ++i) {
            const char* record = pos + i * stride;
            std::memcpy(&out[i].x, record + offset[0], 4);
            std::memcpy(&out[i].y, record + offset[1], 4);
            std::memcpy(&out[i].z, record + offset[2], 4);
        }
    }
    pos += n * stride;
    return true;
}

// The commonest face layout, every face a triangle of valid indices, as
// fixed-size records (before + 13 + after bytes) read by all threads, each
// a range of faces. False, with nothing read, at the first record that is
// not so (or when the file is too short): the serial loop then reads them
// all and names the problem.
bool read_triangles_in_parallel(const char*& pos, const char* end, uint64_t count, size_t before, size_t after,
                                uint64_t nv, std::vector<Face>& faces) {
    const size_t stride = before + 13 + after;
    if (count < 65536 || !faces.empty() || count > uint64_t(end - pos) / stride) return false;
    const size_t n = size_t(count);
    reserve_prefaulted(faces, n);
    faces.resize(n);
    std::atomic<bool> all_triangles{true};
    const char* first = pos;
    parallel_for_ranges(n, [&](size_t begin, size_t last) {
        bool ok = true;
        for (size_t i = begin; i < last && ok; ++i) {
            const char* record = first + i * stride + before;
            uint32_t v[3];
            std::memcpy(v, record + 1, 12);
            ok = uint8_t(record[0]) == 3 && v[0] < nv && v[1] < nv && v[2] < nv;
            faces[i] = Face(v[0], v[1], v[2]);
        }
        if (!ok) all_triangles = false;
    });
    if (!all_triangles) {
        faces.clear();
        return false;
    }
    pos += n * stride;
    return true;
}

// Fast path: faces made of scalars around one list with a one-byte count and
// 32-bit indices, in host order; triangles are copied directly.
bool read_faces_fast(const char*& pos, const char* end, const PlyElement& element, const ElementPlan& plan,
                     ReadContext& ctx, std::vector<Face>& faces) {
    const PlyProperty& list = element.properties[size_t(plan.index_list)];
    if (list.count_type != PlyType::UInt8 && list.count_type != PlyType::Int8) return false;
    if (list.type != PlyType::Int32 && list.type != PlyType::UInt32) return false;
    size_t before = 0, after = 0;
    for (size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& p = element.properties[k];
        if (int(k) == plan.index_list) continue;
        if (p.is_list) return false;
        (int(k) < plan.index_list ? before : after) += ply_type_size(p.type);
    }
    const bool signed_count = list.count_type == PlyType::Int8;
    const bool signed_index = list.type == PlyType::Int32;
    const uint64_t nv = ctx.vertex_count;
    if (read_triangles_in_parallel(pos, end, element.count, before, after, nv, faces)) return true;
    // Room for the triangles the remaining bytes can hold (counts are not trusted).
    uint64_t triangles_left = uint64_t(end - pos) / (before + 13 + after);
    reserve_prefaulted(faces, faces.size() + size_t(std::min(element.count, triangles_left)));
    int64_t polygon[256];
    for (ctx.item = 0; ctx.item < element.count; ++ctx.item) {
        if (size_t(end - pos) < before + 1) fail_truncated(ctx);
        pos += before;
        int count = signed_count ? int(int8_t(*pos)) : int(uint8_t(*pos));
        ++pos;
        if (count < 0) fail_bad_value(ctx, "negative list length " + std::to_string(count));
        if (size_t(end - pos) < size_t(count) * 4 + after) fail_truncated(ctx);
        if (count == 3) {
            uint32_t v[3];
            std::memcpy(v, pos, 12);
            if (v[0] >= nv || v[1] >= nv || v[2] >= nv) {
                for (uint32_t i : v)
                    if (i >= nv)
                        fail_bad_index(ctx.name, "face", ctx.item,
                                       signed_index ? int64_t(int32_t(i)) : int64_t(i), nv);
            }
            faces.emplace_back(v[0], v[1], v[2]);
        } else {
            for (int j = 0; j < count; ++j) {
                uint32_t i;
                std::memcpy(&i, pos + 4 * j, 4);
                polygon[j] = signed_index ? int64_t(int32_t(i)) : int64_t(i);
            }
            add_polygon(ctx.name, "face", ctx.item, polygon, size_t(count), nv, faces);
        }
        pos += size_t(count) * 4 + after;
    }
    return true;
}

ElementPlan plan_element(const PlyElement& e, bool first_vertex_element, const std::string& name) {
    ElementPlan plan;
    if (e.name == "vertex" && first_vertex_element) {
        plan.kind = ElementPlan::Kind::Vertices;
        const char* axes[3] = {"x", "y", "z"};
        for (int a = 0; a < 3; ++a) {
            plan.coord[a] = e.find(axes[a]);
            if (plan.coord[a] < 0)
                fail_load(name, std::string("vertex element has no '") + axes[a] + "' property");
            if (e.properties[size_t(plan.coord[a])].is_list)
                fail_load(name,
                          std::string("vertex property '") + axes[a] + "' is a list, expected a number");
        }
    } else if (e.name == "face" || e.name == "tristrips") {
        plan.kind = e.name == "face" ? ElementPlan::Kind::Faces : ElementPlan::Kind::Strips;
        plan.index_list = e.find("vertex_indices");
        if (plan.index_list < 0) plan.index_list = e.find("vertex_index");
        if (plan.index_list < 0 || !e.properties[size_t(plan.index_list)].is_list)
            fail_load(name, "element " + quoted(e.name) + " has no 'vertex_indices' list property");
    }
    return plan;
}

// Value that restarts a triangle strip: -1, which unsigned types store as
// their largest value.
int64_t strip_restart(PlyType type) {
    switch (type) {
        case PlyType::UInt8: return 0xff;
        case PlyType::UInt16: return 0xffff;
        case PlyType::UInt32: return 0xffffffffLL;
        default: return -1;
    }
}

template <typename Source>
void read_body(Source& source, const PlyHeader& header, const std::string& name, Mesh& mesh,
               bool fast_paths) {
    const PlyElement* vertices = header.find("vertex");
    ReadContext ctx{name};
    ctx.vertex_count = vertices ? size_t(vertices->count) : 0;
    for (const PlyElement& e : header.elements) {
        ElementPlan plan = plan_element(e, &e == vertices, name);
        ctx.element = &e;
        switch (plan.kind) {
            case ElementPlan::Kind::Skip:
                read_element(source, plan, ctx, [](const double*, const int64_t*, size_t) {});
                break;
            case ElementPlan::Kind::Vertices:
                if constexpr (std::is_same_v<Source, BinarySource>) {
                    const char* pos = source.position();
                    if (fast_paths && read_vertices_fast(pos, source.end(), e, plan, ctx, mesh.positions)) {
                        source.set_position(pos);
                        break;
                    }
                }
                reserve_prefaulted(mesh.positions, positions_room(size_t(e.count)));
                read_element(source, plan, ctx, [&](const double* xyz, const int64_t*, size_t) {
                    mesh.positions.emplace_back(to_float(xyz[0]), to_float(xyz[1]), to_float(xyz[2]));
                });
                break;
            case ElementPlan::Kind::Faces:
                if constexpr (std::is_same_v<Source, BinarySource>) {
                    const char* pos = source.position();
                    if (fast_paths && read_faces_fast(pos, source.end(), e, plan, ctx, mesh.faces)) {
                        source.set_position(pos);
                        break;
                    }
                }
                reserve_prefaulted(mesh.faces, mesh.faces.size() + size_t(e.count));
                read_element(source, plan, ctx, [&](const double*, const int64_t* list, size_t n) {
                    add_polygon(name, "face", ctx.item, list, n, ctx.vertex_count, mesh.faces);
                });
                break;
            case ElementPlan::Kind::Strips: {
                int64_t restart = strip_restart(e.properties[size_t(plan.index_list)].type);
                read_element(source, plan, ctx, [&](const double*, const int64_t* list, size_t n) {
                    add_triangle_strips(name, ctx.item, list, n, restart, ctx.vertex_count, mesh.faces);
                });
                break;
            }
        }
    }
}

}  // namespace
}  // namespace io

Mesh read_ply(const char* data, size_t size, const std::string& name) {
    using namespace io;
    PlyHeader header = parse_ply_header(data, size, name);
    const PlyElement* vertices = header.find("vertex");
    if (vertices && vertices->count > std::numeric_limits<uint32_t>::max())
        fail_load(name, "too many vertices (" + std::to_string(vertices->count) + ")");
    Mesh mesh;
    const char* body = data + header.body_offset;
    const char* end = data + size;
    if (header.format == PlyFormat::Ascii) {
        AsciiSource source(data, body, end);
        read_body(source, header, name, mesh, false);
    } else {
        bool file_little = header.format == PlyFormat::BinaryLittleEndian;
        BinarySource source(body, end, file_little != kHostLittleEndian);
        read_body(source, header, name, mesh, file_little == kHostLittleEndian);
    }
    check_loaded_mesh(name, mesh);
    return mesh;
}

}  // namespace kappa
