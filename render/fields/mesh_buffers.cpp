#include "render/fields/mesh_buffers.h"

#include "geometry/lines/line_extraction.h"
#include "geometry/mesh/orientation.h"
#include "geometry/mesh/surface_samples.h"
#include "geometry/curvature/vertex_flags.h"
#include "geometry/parallel/parallel.h"
#include "render/surface/colormap.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <vector>

namespace kappa::render {

namespace {

// Faces per culling cluster: small enough for tight normal cones, large
// enough that a frame has few runs to draw.
constexpr uint32_t kClusterFaces = 256;


void set_attribute(GLuint location, int components, size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, sizeof(GpuVertex),
                          reinterpret_cast<const void*>(offset));
}

// The attribute layout of GpuVertex for the bound VAO and GL_ARRAY_BUFFER
// (locations as in shaders/common/mesh_attributes.glsl).
void set_vertex_attributes() {
    set_attribute(0, 3, offsetof(GpuVertex, position));
    set_attribute(1, 3, offsetof(GpuVertex, normal));
    set_attribute(2, 3, offsetof(GpuVertex, d1));
    set_attribute(3, 3, offsetof(GpuVertex, d2));
    set_attribute(4, 2, offsetof(GpuVertex, curv));
    set_attribute(5, 4, offsetof(GpuVertex, dcurv));
    set_attribute(6, 1, offsetof(GpuVertex, unreliable));
    set_attribute(7, 3, offsetof(GpuVertex, fine_normal));
}

}  // namespace

MeshBuffers::Prepared MeshBuffers::prepare(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                                           const std::vector<glm::vec3>& fine_normals, MeshFacts known) {
    Prepared p;
    p.layout = layout_of(mesh, fields.flags, std::move(known));
    p.upload = prepare_field_upload(mesh, fields, feature_size, fine_normals, p.layout.clusters);
    return p;
}

MeshBuffers::MeshBuffers(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                         const std::vector<glm::vec3>& fine_normals)
    : MeshBuffers(mesh, prepare(mesh, fields, feature_size, fine_normals)) {}

MeshBuffers::MeshBuffers(const Mesh& mesh, Prepared&& prepared)
    : vertex_count_(mesh.vertex_count()), face_count_(mesh.face_count()) {
    build(std::move(prepared.layout));
    upload(std::move(prepared.upload));
}

MeshBuffers::MeshBuffers(const Mesh& mesh, Prepared&& prepared, InSlices)
    : vertex_count_(mesh.vertex_count()), face_count_(mesh.face_count()) {
    check_upload(prepared.upload);
    build(std::move(prepared.layout), false);
    pending_ = std::make_unique<PendingUpload>();
    pending_->fields = std::move(prepared.upload);
    pending_->first_landing = true;
}

size_t MeshBuffers::landing_bytes(const Mesh& mesh) {
    return mesh.face_count() * sizeof(Face) + 2 * mesh.vertex_count() * (sizeof(GpuVertex) + sizeof(glm::vec3));
}

FaceClusters MeshBuffers::face_clusters_of(const Mesh& mesh, const VertexFaces* rows) {
    return cluster_faces(mesh, kClusterFaces, rows);
}

MeshBuffers::MeshLayout MeshBuffers::layout_of(const Mesh& mesh, const std::vector<uint8_t>& flags, MeshFacts known) {
    // The clusters and the back faces both walk the vertex-face rows.
    VertexFaces built;
    const VertexFaces* rows = known.rows;
    if (!rows) built = build_vertex_faces(mesh), rows = &built;
    MeshLayout out;
    FaceClusters clusters = known.clusters ? std::move(*known.clusters) : face_clusters_of(mesh, rows);
    if (clusters.face_order.size() != mesh.face_count() || clusters.vertex_slot.size() != mesh.vertex_count())
        throw std::invalid_argument("MeshBuffers: face clusters of another mesh");
    out.bounds = known.bounds ? *known.bounds : bounding_sphere(mesh);
    out.back_faces = back_face_visibility(mesh, *rows, known.outside_out ? *known.outside_out : is_outside_out(mesh));
    // Triangles in cluster order, so the contour pass can draw runs of them,
    // and vertices in order of first use by those triangles, so a run's
    // vertices lie close together (for the GL's vertex fetch and the CPU
    // line pass alike).
    const std::vector<uint32_t>& new_id = clusters.vertex_slot;
    out.faces.resize(mesh.faces.size());
    parallel_for(out.faces.size(), [&](size_t i) {
        const Face& f = mesh.faces[clusters.face_order[i]];
        out.faces[i] = {new_id[f[0]], new_id[f[1]], new_id[f[2]]};
    });
    out.boundary_edges = boundary_edges(mesh, flags);
    for (glm::uvec2& e : out.boundary_edges) e = {new_id[e.x], new_id[e.y]};
    out.clusters = std::move(clusters);
    return out;
}

void MeshBuffers::build(MeshLayout&& layout, bool send_triangles) {
    bounds_ = layout.bounds;
    back_faces_ = std::move(layout.back_faces);
    face_clusters_ = std::make_shared<const FaceClusters>(std::move(layout.clusters));
    make_vertex_buffers(vertex_buffer_, position_buffer_);
    // The triangles with the whole records (vao_) and with the positions alone (position_vao_).
    glGenVertexArrays(1, &vao_);
    glGenVertexArrays(1, &position_vao_);
    glGenBuffers(1, &triangle_buffer_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangle_buffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(layout.faces.size() * sizeof(Face)),
                 send_triangles ? layout.faces.data() : nullptr, GL_STATIC_DRAW);
    cpu_mesh_.faces = std::move(layout.faces);
    glBindVertexArray(position_vao_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangle_buffer_);

    // Boundary edges share the vertex buffer through a third VAO.
    std::vector<glm::uvec2>& edges = layout.boundary_edges;
    boundary_edges_ = edges.size();
    glGenVertexArrays(1, &edge_vao_);
    glBindVertexArray(edge_vao_);
    glGenBuffers(1, &edge_buffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, edge_buffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(edges.size() * sizeof(glm::uvec2)), edges.data(), GL_STATIC_DRAW);
    cpu_boundary_edges_ = std::move(edges);
    bind_vertex_arrays();
}

void MeshBuffers::bind_vertex_arrays() {
    for (GLuint array : {vao_, edge_vao_}) {
        glBindVertexArray(array);
        glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
        set_vertex_attributes();
    }
    glBindVertexArray(position_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, position_buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void MeshBuffers::update_fields(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                                const std::vector<glm::vec3>& fine_normals) {
    if (mesh.vertex_count() != vertex_count_ || mesh.face_count() != face_count_)
        throw std::invalid_argument("MeshBuffers: new fields for a different mesh");
    upload(prepare_field_upload(mesh, fields, feature_size, fine_normals, *face_clusters_));
}

void MeshBuffers::adopt(FieldUpload&& u) {
    feature_size_ = u.feature_size;
    range_known_ = {};
    seeds_stale_ = true;  // drawn again from the new surface when hatching asks (hatch_seeds)
    cpu_mesh_.positions = std::move(u.copy.positions);
    cpu_fields_ = std::move(u.copy.fields);
    cpu_fine_normals_ = std::move(u.copy.fine_normals);
    clusters_ = std::move(u.clusters);
    static std::atomic<uint64_t> uploads{0};
    fields_version_ = ++uploads;
}

void MeshBuffers::upload(FieldUpload&& u) {
    check_upload(u);
    drop_pending();
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(u.vertices.size() * sizeof(GpuVertex)), u.vertices.data());
    glBindBuffer(GL_ARRAY_BUFFER, position_buffer_);
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(vertex_count_ * sizeof(glm::vec3)), u.copy.positions.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    adopt(std::move(u));
}

void MeshBuffers::begin_upload(FieldUpload&& u) {
    check_upload(u);
    drop_pending();
    pending_ = std::make_unique<PendingUpload>();
    pending_->fields = std::move(u);
    // Into the buffers the last fields but one were drawn from, once there are some: a
    // software GL clears a new buffer (llvmpipe: 0.15-0.7 s for 890 MB).
    if (!spare_vertex_buffer_) make_vertex_buffers(spare_vertex_buffer_, spare_position_buffer_);
}

void MeshBuffers::make_vertex_buffers(GLuint& records, GLuint& positions) const {
    glGenBuffers(1, &records);
    glBindBuffer(GL_ARRAY_BUFFER, records);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertex_count_ * sizeof(GpuVertex)), nullptr, GL_DYNAMIC_DRAW);
    glGenBuffers(1, &positions);
    glBindBuffer(GL_ARRAY_BUFFER, positions);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertex_count_ * sizeof(glm::vec3)), nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void MeshBuffers::check_upload(const FieldUpload& u) const {
    if (u.vertices.size() != vertex_count_ || u.copy.positions.size() != vertex_count_)
        throw std::invalid_argument("MeshBuffers: upload for a different mesh");
}

std::vector<MeshBuffers::UploadPart> MeshBuffers::pending_parts() const {
    std::vector<UploadPart> parts;
    if (!pending_) return parts;
    const PendingUpload& p = *pending_;
    if (p.first_landing)
        parts.push_back({GL_ELEMENT_ARRAY_BUFFER, triangle_buffer_, vao_,
                         reinterpret_cast<const char*>(cpu_mesh_.faces.data()), face_count_ * sizeof(Face)});
    parts.push_back({GL_ARRAY_BUFFER, p.first_landing ? vertex_buffer_ : spare_vertex_buffer_, 0,
                     reinterpret_cast<const char*>(p.fields.vertices.data()), vertex_count_ * sizeof(GpuVertex)});
    parts.push_back({GL_ARRAY_BUFFER, p.first_landing ? position_buffer_ : spare_position_buffer_, 0,
                     reinterpret_cast<const char*>(p.fields.copy.positions.data()), vertex_count_ * sizeof(glm::vec3)});
    return parts;
}

float MeshBuffers::upload_progress() const {
    if (!pending_) return 1;
    size_t total = 0;
    for (const UploadPart& part : pending_parts()) total += part.size;
    return total ? float(double(pending_->bytes_sent) / double(total)) : 1.0f;
}

bool MeshBuffers::upload_step(size_t bytes) { return send_pending(bytes, true); }

void MeshBuffers::finish_upload() {
    while (!send_pending(std::numeric_limits<size_t>::max(), false)) {
    }
}

bool MeshBuffers::send_pending(size_t bytes, bool make_spare) {
    if (!pending_) return true;
    PendingUpload& p = *pending_;
    size_t budget = std::max<size_t>(bytes, 1);
    size_t part_start = 0;  // the part's first byte in the whole upload
    for (const UploadPart& part : pending_parts()) {
        const size_t part_end = part_start + part.size;
        if (budget > 0 && p.bytes_sent < part_end) {
            const size_t at = p.bytes_sent - part_start, size = std::min(budget, part.size - at);
            if (part.vertex_array) glBindVertexArray(part.vertex_array);  // an element buffer is its state
            glBindBuffer(part.target, part.buffer);
            glBufferSubData(part.target, GLintptr(at), GLsizeiptr(size), part.data + at);
            if (part.vertex_array) glBindVertexArray(0);
            p.bytes_sent += size, budget -= size;
        }
        part_start = part_end;
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    if (p.bytes_sent < part_start) return false;
    // A first landing makes the spare buffers for later views too, in a call of its own: made at
    // the first new view, they held that frame (llvmpipe clears them: 0.66 s for a 17.8M-face mesh).
    if (p.first_landing && !spare_vertex_buffer_ && make_spare) {
        make_vertex_buffers(spare_vertex_buffer_, spare_position_buffer_);
        return false;
    }
    // The last slice is sent. New fields: the spare buffers become the drawn ones, and the drawn ones spare.
    if (!p.first_landing) {
        std::swap(vertex_buffer_, spare_vertex_buffer_);
        std::swap(position_buffer_, spare_position_buffer_);
        bind_vertex_arrays();
    }
    FieldUpload done = std::move(p.fields);
    pending_.reset();
    adopt(std::move(done));
    return true;
}

// A pending first landing is finished (the triangles go with it); new fields are dropped
// (their buffers stay spare).
void MeshBuffers::drop_pending() {
    if (pending_ && pending_->first_landing) finish_upload();
    pending_.reset();
}

float MeshBuffers::map_range(ColorMap map) const {
    const size_t m = size_t(map);
    if (!range_known_[m]) ranges_[m] = robust_range(map, cpu_fields_), range_known_[m] = true;
    return ranges_[m];
}

const std::vector<MeshBuffers::Seed>& MeshBuffers::hatch_seeds() {
    if (seeds_stale_) {
        const SurfaceSamples samples = sample_surface(cpu_mesh_, cpu_fields_, kHatchSeeds);
        hatch_seeds_.clear();
        hatch_seeds_.reserve(samples.points.size());
        for (const SurfaceSample& p : samples.points) hatch_seeds_.push_back({p.position, p.normal});
        seeds_stale_ = false;
    }
    return hatch_seeds_;
}

MeshBuffers::~MeshBuffers() {
    const GLuint buffers[] = {vertex_buffer_,  triangle_buffer_,       position_buffer_,      edge_buffer_,
                              crease_buffer_, spare_vertex_buffer_, spare_position_buffer_};
    glDeleteBuffers(GLsizei(std::size(buffers)), buffers);
    const GLuint arrays[] = {vao_, position_vao_, edge_vao_, crease_vao_};
    glDeleteVertexArrays(GLsizei(std::size(arrays)), arrays);
}

void MeshBuffers::set_creases(const std::vector<glm::vec3>& end_points) {
    if (!crease_vao_) {
        glGenVertexArrays(1, &crease_vao_);
        glGenBuffers(1, &crease_buffer_);
        glBindVertexArray(crease_vao_);
        glBindBuffer(GL_ARRAY_BUFFER, crease_buffer_);
        for (GLuint location = 0; location < 3; ++location) {
            glEnableVertexAttribArray(location);
            glVertexAttribPointer(location, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(glm::vec3),
                                  reinterpret_cast<const void*>(location * sizeof(glm::vec3)));
        }
    }
    glBindVertexArray(crease_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, crease_buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(end_points.size() * sizeof(glm::vec3)), end_points.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    creases_ = end_points.size() / 6;
    cpu_creases_ = crease_edges_of(end_points);
}

void MeshBuffers::draw_creases() const {
    if (creases_ == 0) return;
    glBindVertexArray(crease_vao_);
    glDrawArrays(GL_LINES, 0, GLsizei(creases_ * 2));
}

void MeshBuffers::draw_points() const {
    glBindVertexArray(vao_);
    glDrawArrays(GL_POINTS, 0, GLsizei(vertex_count_));
}

namespace {

// glMultiDrawElements over runs of faces, in the bound VAO.
void draw_runs(const std::vector<FaceRun>& runs) {
    if (runs.empty()) return;
    std::vector<GLsizei> counts(runs.size());
    std::vector<const void*> offsets(runs.size());
    for (size_t i = 0; i < runs.size(); ++i) {
        counts[i] = GLsizei(runs[i].count * 3);
        offsets[i] = reinterpret_cast<const void*>(size_t(runs[i].first) * sizeof(Face));
    }
    glMultiDrawElements(GL_TRIANGLES, counts.data(), GL_UNSIGNED_INT, offsets.data(), GLsizei(runs.size()));
}

}  // namespace

void MeshBuffers::draw_triangles() const {
    glBindVertexArray(vao_);
    glDrawElements(GL_TRIANGLES, GLsizei(face_count_ * 3), GL_UNSIGNED_INT, nullptr);
}

void MeshBuffers::draw_triangles(const std::vector<FaceRun>& runs) const {
    glBindVertexArray(vao_);
    draw_runs(runs);
}

void MeshBuffers::draw_triangle_positions(const std::vector<FaceRun>& runs) const {
    glBindVertexArray(position_vao_);
    draw_runs(runs);
}

void MeshBuffers::draw_boundary_edges() const {
    if (boundary_edges_ == 0) return;
    glBindVertexArray(edge_vao_);
    glDrawElements(GL_LINES, GLsizei(boundary_edges_ * 2), GL_UNSIGNED_INT, nullptr);
}

}  // namespace kappa::render
