#include "render/fields/field_upload.h"

#include "geometry/curvature/vertex_flags.h"
#include "geometry/parallel/parallel.h"
#include "render/fields/mesh_buffers.h"

#include <glm/geometric.hpp>

#include <stdexcept>

namespace kappa::render {

FieldUploadSteps::FieldUploadSteps(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                                   const std::vector<glm::vec3>& fine_normals, const FaceClusters& clusters,
                                   size_t chunk) {
    const size_t n = mesh.vertex_count();
    if (fields.normals.size() != n || fields.k1.size() != n || fields.k2.size() != n || fields.d1.size() != n ||
        fields.d2.size() != n || fields.dcurv.size() != n)
        throw std::invalid_argument("MeshBuffers: surface fields do not match the mesh's vertex count");
    const bool own_fine = !fine_normals.empty();
    if (own_fine && fine_normals.size() != n)
        throw std::invalid_argument("MeshBuffers: fine normals do not match the mesh's vertex count");
    if (clusters.vertex_order.size() != n || clusters.vertex_slot.size() != n)
        throw std::invalid_argument("MeshBuffers: face clusters of another mesh");

    FieldUpload& u = upload_;
    u.feature_size = feature_size;
    // Each vertex's record to its place in the clusters' vertex order (vertex_slot): the fields read in their own
    // order and each record written once where it goes (gathered in the clusters' order instead, every
    // record would read eight arrays at a place of its own).
    steps_.add_once([&, n] { u.vertices = UninitializedArray<GpuVertex>(n); });
    steps_.add_chunks(n, chunk, [&, own_fine](size_t first, size_t last) {
        parallel_for(last - first, [&](size_t k) {
            const size_t v = first + k;
            u.vertices[clusters.vertex_slot[v]] = {mesh.positions[v], fields.normals[v], fields.d1[v], fields.d2[v],
                                                   {fields.k1[v], fields.k2[v]}, fields.dcurv[v],
                                                   fields.unreliable(v) ? 1.0f : 0.0f,
                                                   own_fine ? fine_normals[v] : fields.normals[v]};
        });
    });
    // The CPU copy, read back from the records in their order.
    steps_.add_once([&, n] {
        FieldCopy& c = u.copy;
        c.positions.resize(n), c.fine_normals.resize(n);
        SurfaceFields& f = c.fields;
        f.normals.resize(n), f.k1.resize(n), f.k2.resize(n), f.d1.resize(n), f.d2.resize(n), f.dcurv.resize(n);
        f.flags.resize(n);
    });
    steps_.add_chunks(n, chunk, [&](size_t first, size_t last) {
        FieldCopy& c = u.copy;
        SurfaceFields& f = c.fields;
        parallel_for(last - first, [&](size_t k) {
            const size_t i = first + k;
            const GpuVertex& r = u.vertices[i];
            c.positions[i] = r.position, c.fine_normals[i] = r.fine_normal;
            f.normals[i] = r.normal, f.d1[i] = r.d1, f.d2[i] = r.d2;
            f.k1[i] = r.curv.x, f.k2[i] = r.curv.y, f.dcurv[i] = r.dcurv;
            f.flags[i] = r.unreliable > 0 ? kFlagUnreliable : 0;
        });
    });
    steps_.add_once([&] { u.clusters = mesh_cluster_bounds(mesh, fields, clusters, fine_normals); });
    steps_.add_once([&, feature_size] { vertex_bounds_ = vertex_bounds(fields, feature_size); });
    // Clusters of up to 256 faces (render/fields/mesh_buffers.cpp): about as much work as chunk / 64 of them.
    steps_.add_chunks(clusters.size(), chunk == 0 ? 0 : std::max<size_t>(1, chunk / 64),
                      [&](size_t first, size_t last) {
                          bound_cluster_curvature(mesh, clusters, vertex_bounds_, first, last, u.clusters);
                      });
    steps_.add_once([this] { vertex_bounds_ = {}; });
}

FieldUpload prepare_field_upload(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                                 const std::vector<glm::vec3>& fine_normals, const FaceClusters& clusters) {
    FieldUploadSteps steps(mesh, fields, feature_size, fine_normals, clusters, 0);
    while (!steps.done()) steps.step();
    return steps.take();
}

std::vector<glm::vec3> crease_end_points(const SplitMesh& split) {
    std::vector<glm::vec3> out;
    out.reserve(split.creases.size() * 6);
    for (const CreaseEdge& c : crease_edges(split.mesh, split.creases, split.crease_faces))
        out.insert(out.end(), {c.a, c.normal_a, c.normal_b, c.b, c.normal_a, c.normal_b});
    return out;
}

std::vector<CreaseEdge> crease_edges_of(const std::vector<glm::vec3>& end_points) {
    std::vector<CreaseEdge> out;
    out.reserve(end_points.size() / 6);
    for (size_t i = 0; i + 6 <= end_points.size(); i += 6)
        out.push_back({end_points[i], end_points[i + 3], end_points[i + 1], end_points[i + 2]});
    return out;
}

}  // namespace kappa::render
