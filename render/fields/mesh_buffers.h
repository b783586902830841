// The mesh and its curvature fields on the GPU: one interleaved vertex
// buffer (position, normal, d1, d2, k1 k2, C, flags, contour normal),
// the triangles, the open boundary edges, and random surface samples that
// seed hatching strokes (geometry/mesh/surface_samples.h). Every view-dependent quantity
// is computed from these in the shaders, per frame.
#pragma once

#include "geometry/culling/back_faces.h"
#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/surface_fields.h"
#include "render/camera/camera.h"
#include "render/lines/cluster_culling.h"
#include "render/fields/field_upload.h"
#include "render/gl/gl.h"
#include "render/render_settings.h"

#include <array>
#include <memory>
#include <optional>

namespace kappa::render {

// What a caller may already know of a mesh, so that building its buffers need not find it
// again (app/mesh_drawing.cpp keeps the rows, the orientation and the bounds from its
// preparation and makes the clusters while the fields are computed): its vertex-face rows
// (build_vertex_faces), whether its normals point clearly outside (is_outside_out,
// geometry/mesh/orientation.h), its MeshBuffers::face_clusters_of and its bounding_sphere.
// Unknown: found by MeshBuffers::layout_of.
struct MeshFacts {
    const VertexFaces* rows = nullptr;
    std::optional<bool> outside_out;
    std::optional<FaceClusters> clusters;
    std::optional<BoundingSphere> bounds;
};

class MeshBuffers {
public:
    // Uploads; needs a current GL context. fields must have one entry per
    // vertex. feature_size: the mesh's feature size fs (geometry/curvature/feature_size.h).
    MeshBuffers(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                const std::vector<glm::vec3>& fine_normals = {});
    // What building the buffers computes before any GL call, made on any thread (a viewer's
    // worker, so that its window thread only sends; a page with one thread, as a step of its
    // own): the face clusters, the bounding sphere, where back faces can be seen, the
    // triangles in the clusters' order and the open boundary edges, both in the uploaded
    // vertex order. flags: the fields' (open boundaries).
    struct MeshLayout {
        FaceClusters clusters;
        std::vector<Face> faces;
        std::vector<glm::uvec2> boundary_edges;
        BoundingSphere bounds;
        BackFaceVisibility back_faces;
    };
    static MeshLayout layout_of(const Mesh& mesh, const std::vector<uint8_t>& flags, MeshFacts known = {});
    // The face clusters the triangles are uploaded in (geometry/culling/face_clusters.h; one
    // thread: 2 s for 17.8M faces). rows: the mesh's vertex-face rows (null: built here).
    static FaceClusters face_clusters_of(const Mesh& mesh, const VertexFaces* rows = nullptr);
    // Everything the first constructor computes before any GL call: the layout and the
    // fields' upload prepared in its clusters' order (prepare_field_upload; any thread).
    struct Prepared {
        MeshLayout layout;
        FieldUpload upload;
    };
    static Prepared prepare(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                            const std::vector<glm::vec3>& fine_normals = {}, MeshFacts known = {});
    // The same as the first constructor from what was prepared beforehand: GL calls alone.
    MeshBuffers(const Mesh& mesh, Prepared&& prepared);
    // The same sent in slices, for a viewer whose frames must not wait for a big mesh's first
    // view (a 17.8M-face mesh: 213 MB of triangles, 890 MB of vertex records and positions):
    // the buffers are made empty, then upload_step sends the triangles, the records and the
    // positions into them, at most `bytes` a call, and one more call makes the spare buffers
    // that later views' fields go to (begin_upload). Nothing may be drawn from these buffers
    // until upload_step returns true (the viewer keeps them aside until then); a begin_upload,
    // upload or update_fields first sends what is left (without the spare buffers).
    struct InSlices {};
    MeshBuffers(const Mesh& mesh, Prepared&& prepared, InSlices);
    // The bytes of the GL buffers such a landing makes for the mesh (the spare ones included):
    // host memory, on a software GL.
    static size_t landing_bytes(const Mesh& mesh);
    ~MeshBuffers();
    // Replaces the fields (same mesh): vertex attributes, culling bounds,
    // colour-map ranges and hatching seeds. For fields at a new scale.
    // fine_normals: normals at pixel scale, for occluding contours (zeros
    // of n.v) and shading (empty: fields.normals).
    void update_fields(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                       const std::vector<glm::vec3>& fine_normals = {});
    // The same in two halves: prepare_field_upload (render/fields/field_upload.h,
    // any thread, with face_clusters()) then this, on the GL thread.
    void upload(FieldUpload&& prepared);
    // The second half in slices, for a viewer whose frames must not wait for
    // hundreds of MB (a 17.8M-face mesh has 783 MB of vertex records): the
    // records go into a second vertex buffer (kept for the next time: GPU
    // memory for one more copy of the records), at most `bytes` a call of
    // upload_step, while frames draw the fields uploaded before; the call
    // that sends the last slice makes the new fields current (buffers, CPU
    // copy, culling bounds, fields_version) and returns true. A new
    // begin_upload, or an upload or update_fields, drops a pending one.
    void begin_upload(FieldUpload&& prepared);
    bool upload_step(size_t bytes);  // true when nothing is pending any more
    void finish_upload();            // sends what is left at once (a landing: without the spare buffers)
    bool upload_pending() const { return pending_ != nullptr; }
    float upload_progress() const;   // of the pending upload: the fraction of its bytes sent (1: none pending)
    const FaceClusters& face_clusters() const { return *face_clusters_; }
    // The same shared, for a worker that prepares later views' fields in their order (a viewer):
    // no copy of what is, on a 17.8M-face mesh, 150 MB.
    std::shared_ptr<const FaceClusters> shared_face_clusters() const { return face_clusters_; }
    // A CPU copy of what the shaders read, for lines made on the CPU (strokes,
    // the CPU isoline pass): the positions and faces in the uploaded order
    // (faces cluster by cluster, vertices in face_clusters().vertex_order); the fields on the GPU now (normals, k1, k2, d1, d2,
    // C, unreliable vertices as kFlagUnreliable); the pixel-scale contour normals.
    const Mesh& cpu_mesh() const { return cpu_mesh_; }
    const SurfaceFields& cpu_fields() const { return cpu_fields_; }
    const std::vector<glm::vec3>& cpu_fine_normals() const { return cpu_fine_normals_; }
    // The open boundary edges (vertex pairs in the uploaded order), as draw_boundary_edges draws them.
    const std::vector<glm::uvec2>& cpu_boundary_edges() const { return cpu_boundary_edges_; }
    // A number that changes at every upload of fields, different for every
    // MeshBuffers: for what is computed from the fields and kept.
    uint64_t fields_version() const { return fields_version_; }
    MeshBuffers(const MeshBuffers&) = delete;
    MeshBuffers& operator=(const MeshBuffers&) = delete;

    void draw_triangles() const;       // GL_TRIANGLES over every face
    void draw_points() const;          // GL_POINTS over every vertex
    void draw_triangles(const std::vector<FaceRun>& runs) const;  // the faces of these runs (cluster order)
    // The same with only the positions as attribute 0, from a buffer of
    // positions alone: a depth-only pass reads 12 bytes a vertex, not a
    // whole GpuVertex record (a software GL fetches vertices on one thread).
    void draw_triangle_positions(const std::vector<FaceRun>& runs) const;
    void draw_boundary_edges() const;  // GL_LINES over every open boundary edge
    // Sharp edges: per end point its position and the normals of the edge's
    // two faces (3 vec3 each, 2 end points an edge; shaders/lines/crease_vert.glsl).
    void set_creases(const std::vector<glm::vec3>& end_points);
    void draw_creases() const;  // GL_LINES over every crease
    // The same sharp edges on the CPU, for the CPU line pass where the GL has no geometry stage (gles_compat.h).
    const std::vector<CreaseEdge>& cpu_creases() const { return cpu_creases_; }
    size_t crease_count() const { return creases_; }

    // The interleaved vertex records (GpuVertex) and the triangles (three
    // vertex indices a face, cluster order), for the compute line passes.
    GLuint vertex_buffer() const { return vertex_buffer_; }
    GLuint triangle_buffer() const { return triangle_buffer_; }
    // The open boundary edges (vertex index pairs) and the creases (per end
    // point: position, the two faces' normals), for the compute line passes.
    GLuint boundary_edge_buffer() const { return edge_buffer_; }
    GLuint crease_buffer() const { return crease_buffer_; }
    size_t vertex_count() const { return vertex_count_; }
    size_t face_count() const { return face_count_; }
    size_t boundary_edge_count() const { return boundary_edges_; }
    // The seeds of streamline hatching (render/hatching/hatch_streamlines.h):
    // the first kHatchSeeds surface samples of the drawn surface
    // (geometry/mesh/surface_samples.h, in their random order: every prefix
    // is a uniform sample). Drawn when first asked for after the mesh was
    // made or update_fields() gave it new fields (an upload() from a worker
    // keeps them, so strokes stay put while a viewer's fields follow the
    // view): drawings without hatching never pay for them.
    struct Seed {
        glm::vec3 position, normal;
    };
    static constexpr size_t kHatchSeeds = 32768;
    const std::vector<Seed>& hatch_seeds();
    float feature_size() const { return feature_size_; }
    const BoundingSphere& bounds() const { return bounds_; }
    // Whether back faces may be culled, and the holes to draw them in (geometry/culling/back_faces.h).
    const BackFaceVisibility& back_faces() const { return back_faces_; }
    // The faces are uploaded cluster by cluster (render/lines/cluster_culling.h).
    const MeshClusters& clusters() const { return clusters_; }
    // Robust colour-map range (render/surface/colormap.h) of the fields
    // uploaded last, worked out from the CPU copy when a map first asks for
    // it: a drawing pays for the one map it shows, not for all seven.
    float map_range(ColorMap map) const;

private:
    // Everything but the fields: bounds, triangles in cluster order, boundary edges, the buffers.
    // The GL half: buffers and vertex arrays, the triangles sent unless they are to go in slices.
    void build(MeshLayout&& layout, bool send_triangles = true);
    // Makes the uploaded fields current: their CPU copy, bounds and version.
    void adopt(FieldUpload&& uploaded);
    // A buffer for the vertex records and one for the positions alone, of this mesh's size, unfilled.
    void make_vertex_buffers(GLuint& records, GLuint& positions) const;
    // Throws std::invalid_argument when an upload is for another mesh.
    void check_upload(const FieldUpload& u) const;
    // Points the vertex arrays at vertex_buffer_ and position_buffer_.
    void bind_vertex_arrays();
    void drop_pending();
    struct PendingUpload {
        FieldUpload fields;
        // New fields go into the spare buffers, then swap with the drawn ones; a first landing
        // (InSlices) sends the triangles, then the fields, into the drawn buffers themselves.
        bool first_landing = false;
        size_t bytes_sent = 0;  // of the parts in order
    };
    // A stretch of the pending upload: its bytes and the buffer they go to.
    struct UploadPart {
        GLenum target;
        GLuint buffer, vertex_array;  // vertex_array: the one to bind for an element buffer, else 0
        const char* data;
        size_t size;
    };
    std::vector<UploadPart> pending_parts() const;
    bool send_pending(size_t bytes, bool make_spare);  // upload_step's work
    std::unique_ptr<PendingUpload> pending_;
    GLuint spare_vertex_buffer_ = 0, spare_position_buffer_ = 0;  // made by the first begin_upload
    GLuint vao_ = 0, vertex_buffer_ = 0, triangle_buffer_ = 0;
    GLuint position_vao_ = 0, position_buffer_ = 0;  // the positions alone, with triangle_buffer_
    GLuint edge_vao_ = 0, edge_buffer_ = 0;
    GLuint crease_vao_ = 0, crease_buffer_ = 0;
    size_t creases_ = 0;
    size_t vertex_count_ = 0, face_count_ = 0, boundary_edges_ = 0;
    std::vector<Seed> hatch_seeds_;
    bool seeds_stale_ = true;
    float feature_size_ = 1;
    BoundingSphere bounds_;
    BackFaceVisibility back_faces_;
    std::shared_ptr<const FaceClusters> face_clusters_;
    MeshClusters clusters_;
    mutable std::array<float, 7> ranges_{};
    mutable std::array<bool, 7> range_known_{};  // all false after an upload
    Mesh cpu_mesh_;
    SurfaceFields cpu_fields_;
    std::vector<glm::vec3> cpu_fine_normals_;
    std::vector<glm::uvec2> cpu_boundary_edges_;
    std::vector<CreaseEdge> cpu_creases_;
    uint64_t fields_version_ = 0;
};

}  // namespace kappa::render
