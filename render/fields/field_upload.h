// The CPU half of putting curvature fields on the GPU: the interleaved
// vertex records and the culling bounds of the contour pass (colour-map
// ranges and hatching seeds come later, when a drawing asks for them:
// MeshBuffers). No OpenGL: it can be built on a worker
// thread (the viewer prepares fields at a new scale there) and handed to
// MeshBuffers::upload on the GL thread.
#pragma once

#include "geometry/mesh/creases.h"
#include "geometry/lines/line_extraction.h"
#include "geometry/parallel/uninitialized_array.h"
#include "geometry/culling/face_clusters.h"
#include "geometry/mesh/mesh.h"
#include "geometry/parallel/step_queue.h"
#include "geometry/surface_fields.h"
#include "render/lines/cluster_culling.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace kappa::render {

// One vertex as the shaders read it (shaders/common/mesh_attributes.glsl).
struct GpuVertex {
    glm::vec3 position, normal, d1, d2;
    glm::vec2 curv;   // k1, k2
    glm::vec4 dcurv;  // a, b, c, d
    float unreliable;
    glm::vec3 fine_normal;  // pixel-scale normal: contours and shading
};
// Compute passes read the records as 22 floats (shaders/common/mesh_vertex_fetch.glsl).
static_assert(sizeof(GpuVertex) == 22 * sizeof(float), "GpuVertex must stay 22 packed floats");

// The same records as arrays on the CPU, in the same order, for what is made
// on the CPU from what the GPU draws (MeshBuffers::cpu_fields): positions,
// fields (normals, k1, k2, d1, d2, C, flags: kFlagUnreliable alone) and the
// pixel-scale normals.
struct FieldCopy {
    std::vector<glm::vec3> positions;
    SurfaceFields fields;
    std::vector<glm::vec3> fine_normals;
};

struct FieldUpload {
    UninitializedArray<GpuVertex> vertices;  // in FaceClusters::vertex_order; filled whole by the threads
    FieldCopy copy;                          // made beside them, off the GL thread
    MeshClusters clusters;
    float feature_size = 1;
};

// fields: one entry per vertex; fine_normals: empty (use fields.normals) or
// one per vertex; clusters: the face clusters the triangles were uploaded
// in (the vertex records come in its vertex_order).
// Throws std::invalid_argument when sizes do not match the mesh.
FieldUpload prepare_field_upload(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                                 const std::vector<glm::vec3>& fine_normals, const FaceClusters& clusters);

// The same in steps of `chunk` vertices (or as much work in clusters; 0: each part in
// one step), for a page with one thread that prepares a view between its
// frames (app/mesh_drawing.h): the same bits. The arguments must outlive it.
class FieldUploadSteps {
public:
    FieldUploadSteps(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                     const std::vector<glm::vec3>& fine_normals, const FaceClusters& clusters, size_t chunk);
    FieldUploadSteps(const FieldUploadSteps&) = delete;  // its steps point at it
    FieldUploadSteps& operator=(const FieldUploadSteps&) = delete;
    bool done() const { return steps_.done(); }
    void step() { steps_.step(); }
    bool run_for(double seconds) { return steps_.run_for(seconds); }
    FieldUpload take() { return std::move(upload_); }  // once done

private:
    FieldUpload upload_;
    std::vector<VertexBounds> vertex_bounds_;
    StepQueue steps_;
};

// The crease pass's vertex data (MeshBuffers::set_creases): for each crease
// of the split mesh, both end points, each with the unit normals of the
// edge's two faces.
std::vector<glm::vec3> crease_end_points(const SplitMesh& split);
// The sharp edges back from that data (for CPU strokes, render/vector/strokes.h).
std::vector<CreaseEdge> crease_edges_of(const std::vector<glm::vec3>& end_points);

}  // namespace kappa::render
