#include "render/lines/cpu_lines.h"

#include "geometry/lines/chain.h"
#include "geometry/lines/curvature_lines.h"
#include "geometry/lines/level_lines.h"
#include "geometry/lines/line_extraction.h"
#include "geometry/lines/view_quantities.h"
#include "geometry/lines/view_ridges.h"
#include "geometry/parallel/parallel.h"
#include "render/lines/cluster_culling.h"
#include "render/lines/line_prefilter.h"
#include "render/lines/screen_merge.h"
#include "render/lines/view_independent_lines.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cstddef>
#include <utility>

namespace kappa::render {

namespace {

// A corner of a segment's quad (shaders/lines/segment_quads_vert.glsl).
struct QuadVertex {
    glm::vec3 end0, end1;  // window coordinates
    glm::vec2 alpha;
    float tolerance;
    float exterior_corner;  // 8 on_surface + 4 exterior_only + corner
    float width;            // pixels; 0: the line width
};

// What segment_quads_vert.glsl needs of a segment: its window coordinates
// and final occlusion tolerance.
struct WindowParams {
    glm::mat4 mvp;
    glm::vec2 viewport;
    float scale_tolerance;  // detail (px) x pixel size per unit of camera distance; 0 without detail
    bool silhouette_only;   // contours only where they border the background
};

// The segments of `polylines` (of one line type), merged on screen
// (render/lines/screen_merge.h), in window coordinates, appended to `out`; those
// with no ink, behind the eye or beyond the depth range (the GL would clip
// their quad) left out. merged: scratch.
void append_polylines(LineType type, const std::vector<Polyline>& polylines, const ScreenMergeParams& merge,
                      const WindowParams& w, std::vector<LineSegment>& merged, std::vector<WindowSegment>& out) {
    auto to_window = [&](glm::vec4 clip) {
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        return glm::vec3((glm::vec2(ndc) * 0.5f + 0.5f) * w.viewport, ndc.z * 0.5f + 0.5f);
    };
    // As isolines_geom.glsl: 2 occluding contours, 1 the other zero sets of view-dependent fields.
    const int kind = type == LineType::Contour ? 2 : is_view_isoline(type) ? 1 : 0;
    merged.clear();
    for (const Polyline& line : polylines) merge_on_screen(line, merge, merged);
    for (const LineSegment& seg : merged) {
        if (std::max(seg.opacity_a, seg.opacity_b) <= 0.0f) continue;
        const glm::vec4 clip0 = w.mvp * glm::vec4(seg.a, 1.0f), clip1 = w.mvp * glm::vec4(seg.b, 1.0f);
        if (clip0.w <= 0.0f || clip1.w <= 0.0f) continue;
        WindowSegment ws;
        ws.a = to_window(clip0), ws.b = to_window(clip1);
        const float z = std::min(ws.a.z, ws.b.z);  // the quad's depth
        if (!(z >= 0.0f && z <= 1.0f)) continue;
        ws.alpha = {seg.opacity_a, seg.opacity_b};
        ws.tolerance = std::max(seg.tolerance, kind > 0 ? w.scale_tolerance * std::max(clip0.w, clip1.w) : 0.0f);
        ws.exterior_only = kind == 2 && w.silhouette_only;
        out.push_back(ws);
    }
}

// A run of faces and the families to extract on it.
struct MaskedRun {
    uint32_t first, count;
    uint8_t families;
};

// Faces [block * kLineBlockFaces, (block + 1) * kLineBlockFaces) and the
// runs in it that need extraction (render/lines/view_independent_lines.h keeps
// segments by the same blocks). Blocks are fixed, whatever the culling
// keeps, so segments are chained and merged on screen
// (render/lines/screen_merge.h) the same way with culling as without: culled
// clusters hold no lines.
struct Block {
    std::vector<MaskedRun> runs;
};

// The union of each family's runs (each sorted and disjoint), cut where the
// set of families changes and at block boundaries, grouped by block.
std::vector<Block> blocks_of(const std::vector<std::pair<uint8_t, std::vector<FaceRun>>>& families) {
    std::vector<std::pair<uint32_t, int>> events;  // (face, +family bit on / -family bit off)
    for (const auto& [bit, runs] : families)
        for (const FaceRun& r : runs) {
            events.push_back({r.first, int(bit)});
            events.push_back({r.first + r.count, -int(bit)});
        }
    std::sort(events.begin(), events.end());
    std::vector<Block> out;
    uint32_t out_block = ~0u;
    uint8_t mask = 0;
    for (size_t i = 0; i < events.size();) {
        const uint32_t at = events[i].first;
        for (; i < events.size() && events[i].first == at; ++i)
            mask = events[i].second > 0 ? uint8_t(mask | events[i].second) : uint8_t(mask & ~(-events[i].second));
        const uint32_t next = i < events.size() ? events[i].first : at;
        for (uint32_t first = at; mask && first < next;) {
            const uint32_t block = first / kLineBlockFaces, end = std::min(next, (block + 1) * kLineBlockFaces);
            if (block != out_block) out.emplace_back(), out_block = block;
            out.back().runs.push_back({first, end - first, mask});
            first = end;
        }
    }
    return out;
}

}  // namespace

CpuLinePass::CpuLinePass()
    : program_({{GL_VERTEX_SHADER, {"lines/segment_quads_vert.glsl"}}, {GL_FRAGMENT_SHADER, {"lines/lines_frag.glsl"}}}) {
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &buffer_);
    glGenBuffers(1, &index_buffer_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
    const GLsizei stride = sizeof(QuadVertex);
    const struct {
        GLint components;
        size_t offset;
    } attributes[] = {{3, offsetof(QuadVertex, end0)}, {3, offsetof(QuadVertex, end1)}, {2, offsetof(QuadVertex, alpha)},
                      {1, offsetof(QuadVertex, tolerance)}, {1, offsetof(QuadVertex, exterior_corner)},
                      {1, offsetof(QuadVertex, width)}};
    for (GLuint i = 0; i < 6; ++i) {
        glEnableVertexAttribArray(i);
        glVertexAttribPointer(i, attributes[i].components, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(attributes[i].offset));
    }
    glBindVertexArray(0);
}

CpuLinePass::~CpuLinePass() {
    glDeleteBuffers(1, &index_buffer_);
    glDeleteBuffers(1, &buffer_);
    glDeleteVertexArrays(1, &vao_);
}

void CpuLinePass::ensure_indices(size_t quads) {
    if (quads <= index_quads_) return;
    index_quads_ = std::max(quads, 2 * index_quads_);
    std::vector<uint32_t> indices(6 * index_quads_);
    for (size_t q = 0; q < index_quads_; ++q) {
        const uint32_t v = uint32_t(4 * q);
        const uint32_t quad[6] = {v, v + 1, v + 2, v + 2, v + 1, v + 3};
        std::copy(quad, quad + 6, indices.begin() + std::ptrdiff_t(6 * q));
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data(), GL_STATIC_DRAW);
}

CpuLines CpuLinePass::prepare(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& s) const {
    const LineSelection& l = s.lines;
    const Mesh& m = mesh.cpu_mesh();
    const SurfaceFields& fields = mesh.cpu_fields();
    const float fs = mesh.feature_size();
    const float margin = 0.5f * s.line_width + 2.0f;  // pixels a line may reach beyond its centre
    const std::vector<FaceRun> all{{0, uint32_t(m.face_count())}};
    auto runs_or_all = [&](auto runs) { return s.cull_clusters ? runs() : all; };
    LineExtractionOptions o;
    o.contours = l.any_contours(), o.suggestive = l.suggestive, o.suggestive_highlights = l.suggestive_highlights;
    o.dwkr = l.dwkr, o.ridges = l.ridges, o.valleys = l.valleys, o.parabolic = l.parabolic, o.mean_zero = l.mean_zero;
    o.isophotes = l.isophotes && s.isophote_count > 0, o.topo = l.topo && s.topo_count > 0;
    o.sc_threshold = s.sc_threshold, o.sh_threshold = s.sh_threshold, o.rv_threshold = s.rv_threshold;
    o.feature_size = fs, o.fade = s.fade;
    o.cull_back_faces = !s.hidden_lines;  // as rtsc: no line but contours on triangles turned away

    const bool view_lines = o.contours || o.suggestive || o.suggestive_highlights || o.dwkr;
    const bool highlights = l.suggestive_highlights;
    ViewRidgeOptions vr;
    vr.apparent_ridges = l.apparent_ridges, vr.principal_highlights = l.principal_highlights;
    vr.ar_threshold = s.ar_threshold, vr.ph_threshold = s.ph_threshold, vr.feature_size = fs, vr.fade = s.fade;
    // Level lines: isophotes with the shading's light (model coordinates), topographic lines along y.
    LineExtractionOptions levels = o;
    levels.light = glm::normalize(glm::transpose(frame.normal_matrix) * camera_light_direction(s, frame));
    levels.isophote_levels = isophote_level_set(s.isophote_count);
    levels.topo_levels = topo_level_set(mesh.bounds().center.y, mesh.bounds().radius, s.topo_count);

    // Per family, the clusters that can hold its lines in this view (render/lines/cluster_culling.h).
    std::vector<std::pair<uint8_t, std::vector<FaceRun>>> families;
    if (view_lines)
        families.push_back({kViewLines, runs_or_all([&] {
                                return contour_pass_runs(mesh.clusters(), frame, o.contours, o.suggestive || highlights,
                                                         highlights ? -1e30f : s.sc_threshold, margin, o.dwkr);
                            })});
    if (l.curvature_lines())
        families.push_back({kCurvatureLines, runs_or_all([&] {
                                return curvature_line_runs(mesh.clusters(), frame, s.hidden_lines, margin, l,
                                                           s.rv_threshold);
                            })});
    if (l.view_ridges())
        families.push_back({kViewRidges, runs_or_all([&] {
                                return view_ridge_runs(mesh.clusters(), frame, s.hidden_lines, margin, l,
                                                       s.ph_threshold);
                            })});
    if (o.isophotes)
        families.push_back({kIsophotes, runs_or_all([&] {
                                return isophote_runs(mesh.clusters(), frame, s.hidden_lines, margin, levels.light,
                                                     levels.isophote_levels);
                            })});
    if (o.topo)
        families.push_back({kTopo, runs_or_all([&] {
                                return topo_runs(mesh.clusters(), frame, s.hidden_lines, margin, levels.topo_levels);
                            })});
    const std::vector<Block> blocks = blocks_of(families);
    // The segments of ridges, valleys, parabolic, H = 0 and topographic lines
    // are kept between frames; the rest are extracted per frame.
    view_independent_.use(mesh, levels);
    constexpr uint8_t kept_families = kCurvatureLines | kTopo;
    LineExtractionOptions per_view = levels;
    per_view.ridges = per_view.valleys = per_view.parabolic = per_view.mean_zero = per_view.topo = false;

    // Per vertex, once, at the vertices of the triangles some per-view family
    // will test (the rest of the mesh is culled): what the per-face tests read.
    std::vector<uint8_t>& needed = scratch_.needed;
    needed.assign(m.vertex_count(), 0);
    for (const Block& block : blocks)
        for (const MaskedRun& r : block.runs)
            if (r.families & ~kept_families)
                for (uint32_t f = r.first; f < r.first + r.count; ++f)
                    for (int k = 0; k < 3; ++k) needed[m.faces[f][k]] = 1;
    // What the per-face tests read, kept from frame to frame (only the
    // entries at needed vertices are written and read), made in one pass over
    // the vertices, each range of them through every step while in cache.
    const size_t n = m.vertex_count();
    ViewQuantities& q = scratch_.quantities;
    if (view_lines) q.ndotv.resize(n), q.contour_ndotv.resize(n), q.kr.resize(n), q.sc_strength.resize(n);
    else q = {};
    std::vector<ViewRidgeVertex>& ridge_vertices = scratch_.ridge_vertices;
    ridge_vertices.resize(l.view_ridges() ? n : 0);
    LevelValues& level = scratch_.levels;
    begin_level_values(n, per_view, level);
    LinePrefilter& prefilter = scratch_.prefilter;
    begin_line_prefilter(n, vr, per_view, frame.eye, prefilter);
    parallel_for_ranges(n, [&](size_t begin, size_t end) {
        constexpr size_t kInCache = 1024;  // vertices: about 200 bytes each are read and written
        for (size_t first = begin; first < end; first += kInCache) {
            const size_t last = std::min(end, first + kInCache);
            if (view_lines)
                compute_view_quantities(m, fields, mesh.cpu_fine_normals(), frame.eye, fs, needed, first, last, q);
            if (l.view_ridges()) view_ridge_vertices(m, fields, frame.eye, fs, needed, first, last, ridge_vertices);
            level_values(m, fields, per_view, first, last, level);
            line_prefilter_bits(m, fields, q, ridge_vertices, level, needed, first, last, prefilter);
        }
    });

    // One pass over the faces for every family, block by block, the blocks
    // taken by the workers as they come free; each block writes its own
    // vertices, joined in block order (the same buffer for any thread count).
    ScreenMergeParams merge;
    merge.mvp = frame.mvp, merge.viewport = frame.viewport;
    merge.depth_params = glm::vec2(frame.projection[2][2], frame.projection[3][2]);
    WindowParams window;
    window.mvp = frame.mvp, window.viewport = frame.viewport;
    window.scale_tolerance = s.detail * 2.0f / (frame.projection[1][1] * frame.viewport.y);
    window.silhouette_only = l.silhouette && !l.contours;
    // Boundary edges (not culled, as the GL pass drew them all) after the blocks of faces; then, where
    // the GL has no geometry stage to draw them (gles_compat.h), the sharp edges.
    const bool boundaries = l.boundaries && !mesh.cpu_boundary_edges().empty();
    const bool creases = kGles && (l.creases || l.any_contours()) && !mesh.cpu_creases().empty();
    const size_t boundary_block = blocks.size(), crease_block = blocks.size() + size_t(boundaries);
    std::vector<std::vector<WindowSegment>> block_segments(crease_block + size_t(creases));
    parallel_for_dynamic(block_segments.size(), [&](size_t i) {
        thread_local ExtractedLines found;  // kept per worker: its vectors' storage is reused
        thread_local std::vector<LineSegment> merged;
        for (auto& segments : found) segments.clear();
        if (boundaries && i == boundary_block) {
            auto& edges = found[int(LineType::Boundary)];
            append_boundary_segments(m, mesh.cpu_boundary_edges(), edges);
            append_polylines(LineType::Boundary, chain_segments(edges), merge, window, merged, block_segments[i]);
            return;
        }
        if (creases && i == crease_block) {
            LineExtractionOptions edges = o;
            edges.creases = l.creases, edges.hidden_creases = s.hidden_lines;
            append_crease_segments(mesh.cpu_creases(), frame.eye, edges, found);
            for (LineType type : {LineType::Crease, LineType::Contour})
                append_polylines(type, chain_segments(found[int(type)]), merge, window, merged, block_segments[i]);
            return;
        }
        for (const MaskedRun& r : blocks[i].runs) {
            if (r.families & kept_families)
                view_independent_.append_faces(r.first, r.count, m, fields, o.cull_back_faces, frame.eye, found);
            const uint8_t wanted = r.families & ~kept_families;
            if (!wanted) continue;
            for (uint32_t f = r.first; f < r.first + r.count; ++f) {
                const Face& face = m.faces[f];
                const uint8_t families = prefilter.families_on(face, wanted);
                if (!families) continue;
                if (families & kViewLines) extract_view_lines_of_face(m, face, fields, q, o, found);
                if (families & kViewRidges)
                    view_ridges_of_face(m, face, fields, ridge_vertices, vr, found[int(LineType::ApparentRidge)],
                                        found[int(LineType::PrincipalHighlight)]);
                if (families & kIsophotes) level_lines_of_face(m, face, level, per_view, found);
            }
        }
        for (int type = 0; type < kLineTypeCount; ++type)
            if (!found[size_t(type)].empty())
                append_polylines(LineType(type), chain_segments(found[size_t(type)]), merge, window, merged,
                                 block_segments[i]);
    });
    CpuLines lines;
    lines.blocks = std::move(block_segments);
    for (const auto& b : lines.blocks) lines.segment_count += b.size();
    return lines;
}

InkArea CpuLinePass::draw(const CpuLines& lines, const std::vector<WindowSegment>& strokes, const FrameParams& frame,
                          const RenderSettings& s, GLuint depth_texture, GLuint coverage_texture,
                          const std::vector<float>* cpu_depth) {
    InkArea ink;
    const int w = int(frame.viewport.x), h = int(frame.viewport.y);
    if (coverage_texture != 0 && lines.segment_count + strokes.size() > 0) {
        // On the CPU: the surface's depth (read back unless drawn on the CPU), the coverage written over the
        // cleared target.
        if (!cpu_depth) {
            depth_.resize(size_t(w) * size_t(h));
            glBindTexture(GL_TEXTURE_2D, depth_texture);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth_.data());
        }
        std::vector<WindowSegment> all;
        all.reserve(lines.segment_count + strokes.size());
        for (const auto& b : lines.blocks) all.insert(all.end(), b.begin(), b.end());
        all.insert(all.end(), strokes.begin(), strokes.end());
        LineRasterParams p;
        p.width = w, p.height = h, p.line_width = s.line_width, p.hidden_lines = s.hidden_lines;
        p.depth_params = glm::vec2(frame.projection[2][2], frame.projection[3][2]);
        coverage_.assign(size_t(w) * size_t(h), 0);
        rasterize_lines(all, cpu_depth ? *cpu_depth : depth_, p, coverage_);
        glBindTexture(GL_TEXTURE_2D, coverage_texture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RED, GL_UNSIGNED_BYTE, coverage_.data());
        glBindTexture(GL_TEXTURE_2D, depth_texture);
        ink.rects = inked_rectangles(coverage_, w, h);
        return ink;
    }
    // Through the GL: four corners a segment; the strokes too where the GL has no geometry stage for
    // their own pass (gles_compat.h).
    const std::vector<WindowSegment> none;
    const std::vector<WindowSegment>& quad_strokes = kGles ? strokes : none;
    const size_t quads = lines.segment_count + quad_strokes.size();
    if (quads == 0) return ink;
    ink.anywhere = true;
    std::vector<QuadVertex> corners;
    corners.reserve(4 * quads);
    auto add_corners = [&](const WindowSegment& seg) {
        for (int corner = 0; corner < 4; ++corner)
            corners.push_back({seg.a, seg.b, seg.alpha, seg.tolerance,
                               float(8 * int(seg.on_surface) + 4 * int(seg.exterior_only) + corner), seg.width});
    };
    for (const auto& b : lines.blocks)
        for (const WindowSegment& seg : b) add_corners(seg);
    for (const WindowSegment& seg : quad_strokes) add_corners(seg);
    glBindVertexArray(vao_);
    ensure_indices(quads);
    program_.use();
    program_.set("u_viewport", frame.viewport);
    program_.set("u_line_width", s.line_width);
    program_.set("u_depth", 0);
    program_.set("u_depth_params", glm::vec2(frame.projection[2][2], frame.projection[3][2]));
    program_.set("u_hidden_lines", int(s.hidden_lines));
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(corners.size() * sizeof(QuadVertex)), corners.data(), GL_STREAM_DRAW);
    glDrawElements(GL_TRIANGLES, GLsizei(quads * 6), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    return ink;
}

}  // namespace kappa::render
