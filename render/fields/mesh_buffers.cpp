#include "render/fields/mesh_buffers.h"

#include "geometry/lines/line_extraction.h"
#include "geometry/mesh/surface_samples.h"
#include "geometry/curvature/vertex_flags.h"
#include "geometry/parallel/parallel.h"
#include "render/surface/colormap.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <iterator>
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

FaceClusters MeshBuffers::face_clusters_of(const Mesh& mesh) { return cluster_faces(mesh, kClusterFaces); }

MeshBuffers::MeshBuffers(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                         const std::vector<glm::vec3>& fine_normals)
    : vertex_count_(mesh.vertex_count()), face_count_(mesh.face_count()) {
    build(mesh, fields.flags, face_clusters_of(mesh));
    upload(prepare_field_upload(mesh, fields, feature_size, fine_normals, face_clusters_));
}

MeshBuffers::MeshBuffers(const Mesh& mesh, const std::vector<uint8_t>& flags, FaceClusters clusters,
                         FieldUpload&& prepared)
    : vertex_count_(mesh.vertex_count()), face_count_(mesh.face_count()) {
    build(mesh, flags, std::move(clusters));
    upload(std::move(prepared));
}

void MeshBuffers::build(const Mesh& mesh, const std::vector<uint8_t>& flags, FaceClusters clusters) {
    bounds_ = bounding_sphere(mesh);
    back_faces_ = back_face_visibility(mesh);

    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(1, &vertex_buffer_);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertex_count_ * sizeof(GpuVertex)), nullptr, GL_DYNAMIC_DRAW);
    set_vertex_attributes();
    // Triangles in cluster order, so the contour pass can draw runs of them,
    // and vertices in order of first use by those triangles, so a run's
    // vertices lie close together (for the GL's vertex fetch and the CPU
    // line pass alike).
    face_clusters_ = std::move(clusters);
    const std::vector<uint32_t>& new_id = face_clusters_.vertex_slot;
    std::vector<Face> ordered(mesh.faces.size());
    for (size_t i = 0; i < ordered.size(); ++i) {
        const Face& f = mesh.faces[face_clusters_.face_order[i]];
        ordered[i] = {new_id[f[0]], new_id[f[1]], new_id[f[2]]};
    }
    glGenBuffers(1, &triangle_buffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangle_buffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(ordered.size() * sizeof(Face)), ordered.data(), GL_STATIC_DRAW);
    cpu_mesh_.faces = std::move(ordered);
    glGenVertexArrays(1, &position_vao_);
    glBindVertexArray(position_vao_);
    glGenBuffers(1, &position_buffer_);
    glBindBuffer(GL_ARRAY_BUFFER, position_buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertex_count_ * sizeof(glm::vec3)), nullptr, GL_DYNAMIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangle_buffer_);

    // Boundary edges share the vertex buffer through a second VAO.
    std::vector<glm::uvec2> edges = boundary_edges(mesh, flags);
    for (glm::uvec2& e : edges) e = {new_id[e.x], new_id[e.y]};
    boundary_edges_ = edges.size();
    glGenVertexArrays(1, &edge_vao_);
    glBindVertexArray(edge_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    set_vertex_attributes();
    glGenBuffers(1, &edge_buffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, edge_buffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(edges.size() * sizeof(glm::uvec2)), edges.data(), GL_STATIC_DRAW);
    cpu_boundary_edges_ = std::move(edges);

    glBindVertexArray(0);
}

void MeshBuffers::update_fields(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                                const std::vector<glm::vec3>& fine_normals) {
    if (mesh.vertex_count() != vertex_count_ || mesh.face_count() != face_count_)
        throw std::invalid_argument("MeshBuffers: new fields for a different mesh");
    upload(prepare_field_upload(mesh, fields, feature_size, fine_normals, face_clusters_));
}

// The CPU copy of what the shaders read (for CPU line extraction and strokes).
void MeshBuffers::keep_cpu_copy(const UninitializedArray<GpuVertex>& v) {
    const size_t n = v.size();
    SurfaceFields& f = cpu_fields_;
    cpu_mesh_.positions.resize(n);
    f.normals.resize(n), f.k1.resize(n), f.k2.resize(n), f.d1.resize(n), f.d2.resize(n), f.dcurv.resize(n);
    f.flags.resize(n), cpu_fine_normals_.resize(n);
    parallel_for(n, [&](size_t i) {
        cpu_mesh_.positions[i] = v[i].position;
        f.normals[i] = v[i].normal, f.d1[i] = v[i].d1, f.d2[i] = v[i].d2;
        f.k1[i] = v[i].curv.x, f.k2[i] = v[i].curv.y, f.dcurv[i] = v[i].dcurv;
        f.flags[i] = v[i].unreliable > 0 ? kFlagUnreliable : 0;
        cpu_fine_normals_[i] = v[i].fine_normal;
    });
}

void MeshBuffers::upload(FieldUpload&& u) {
    if (u.vertices.size() != vertex_count_) throw std::invalid_argument("MeshBuffers: upload for a different mesh");
    feature_size_ = u.feature_size;
    range_known_ = {};
    seeds_stale_ = true;  // drawn again from the new surface when hatching asks (hatch_seeds)
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(u.vertices.size() * sizeof(GpuVertex)), u.vertices.data());
    keep_cpu_copy(u.vertices);
    static std::atomic<uint64_t> uploads{0};
    fields_version_ = ++uploads;
    glBindBuffer(GL_ARRAY_BUFFER, position_buffer_);
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(cpu_mesh_.positions.size() * sizeof(glm::vec3)),
                    cpu_mesh_.positions.data());
    clusters_ = std::move(u.clusters);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
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
    const GLuint buffers[] = {vertex_buffer_, triangle_buffer_, position_buffer_, edge_buffer_, crease_buffer_};
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
