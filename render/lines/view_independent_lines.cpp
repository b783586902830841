#include "render/lines/view_independent_lines.h"

#include "geometry/lines/curvature_lines.h"
#include "render/fields/mesh_buffers.h"

#include <algorithm>

namespace kappa::render {

namespace {

// Only the options these types read, with every other type off.
LineExtractionOptions view_independent_options(const LineExtractionOptions& o) {
    LineExtractionOptions k;
    k.contours = k.suggestive = k.boundaries = k.creases = k.suggestive_highlights = k.dwkr = false;
    k.isophotes = k.apparent_ridges = k.principal_highlights = false;
    k.ridges = o.ridges, k.valleys = o.valleys, k.parabolic = o.parabolic, k.mean_zero = o.mean_zero;
    k.topo = o.topo && o.topo_levels.count > 0;
    k.rv_threshold = o.rv_threshold, k.feature_size = o.feature_size, k.fade = o.fade;
    k.topo_levels = o.topo_levels;
    return k;
}

bool same(const LineExtractionOptions& a, const LineExtractionOptions& b) {
    return a.ridges == b.ridges && a.valleys == b.valleys && a.parabolic == b.parabolic && a.mean_zero == b.mean_zero &&
           a.topo == b.topo && a.rv_threshold == b.rv_threshold && a.feature_size == b.feature_size &&
           a.fade == b.fade && a.topo_levels.first == b.topo_levels.first &&
           a.topo_levels.step == b.topo_levels.step && a.topo_levels.count == b.topo_levels.count;
}

}  // namespace

void ViewIndependentLines::use(const MeshBuffers& mesh, const LineExtractionOptions& options) {
    const LineExtractionOptions o = view_independent_options(options);
    if (fields_version_ == mesh.fields_version() && same(o, options_) && !blocks_.empty()) return;
    fields_version_ = mesh.fields_version();
    options_ = o;
    const Mesh& m = mesh.cpu_mesh();
    levels_ = o.topo ? level_values(m, SurfaceFields{}, o) : LevelValues{};  // heights only: isophotes are off
    blocks_.clear();
    blocks_.resize((m.face_count() + kLineBlockFaces - 1) / kLineBlockFaces);
}

const ViewIndependentLines::Block& ViewIndependentLines::block(uint32_t b, const Mesh& m, const SurfaceFields& fields) {
    std::unique_ptr<Block>& kept = blocks_[b];
    if (kept) return *kept;
    kept = std::make_unique<Block>();
    thread_local ExtractedLines found;  // kept per worker: its vectors' storage is reused
    const uint32_t first = b * kLineBlockFaces;
    const uint32_t end = uint32_t(std::min<size_t>(m.face_count(), size_t(first) + kLineBlockFaces));
    kept->face_start.assign(kLineBlockFaces + 1, 0);
    for (uint32_t f = first; f < end; ++f) {
        for (auto& segments : found) segments.clear();
        if (options_.ridges || options_.valleys || options_.parabolic || options_.mean_zero)
            curvature_lines_of_face(m, m.faces[f], fields, options_, found);
        if (options_.topo) level_lines_of_face(m, m.faces[f], levels_, options_, found);
        for (int type = 0; type < kLineTypeCount; ++type)
            for (const LineSegment& s : found[size_t(type)]) kept->segments.push_back(s), kept->types.push_back(uint8_t(type));
        kept->face_start[f - first + 1] = uint32_t(kept->segments.size());
    }
    for (uint32_t f = end - first; f < kLineBlockFaces; ++f) kept->face_start[f + 1] = kept->face_start[f];
    return *kept;
}

void ViewIndependentLines::append_faces(uint32_t first, uint32_t count, const Mesh& mesh, const SurfaceFields& fields,
                                        bool cull_back_faces, glm::vec3 eye, ExtractedLines& lines) {
    const uint32_t b = first / kLineBlockFaces;
    const Block& kept = block(b, mesh, fields);
    const uint32_t local = first - b * kLineBlockFaces;
    for (uint32_t f = local; f < local + count; ++f) {
        const uint32_t begin = kept.face_start[f], end = kept.face_start[f + 1];
        if (begin == end || (cull_back_faces && !faces_eye(mesh, fields, mesh.faces[first - local + f], eye))) continue;
        for (uint32_t s = begin; s < end; ++s) lines[kept.types[s]].push_back(kept.segments[s]);
    }
}

}  // namespace kappa::render
