#include "mesh_stats.h"

#include "degenerate.h"
#include "geometry/parallel/parallel.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>

namespace kappa {

BoundingBox bounding_box(const Mesh& mesh) {
    BoundingBox box;
    if (mesh.positions.empty()) return box;
    box.min = box.max = mesh.positions[0];
    for (const glm::vec3& p : mesh.positions) {
        box.min = glm::min(box.min, p);
        box.max = glm::max(box.max, p);
    }
    return box;
}

EdgeLengthStats edge_length_stats(const Mesh& mesh, const EdgeTable& edges) {
    EdgeLengthStats s;
    const size_t n = edges.size();
    if (n == 0) return s;
    std::vector<float> lengths(n);
    parallel_for(n, [&](size_t e) {
        lengths[e] = glm::distance(mesh.positions[edges.ends[e].x], mesh.positions[edges.ends[e].y]);
    });
    double sum = 0;
    s.min = s.max = lengths[0];
    for (float l : lengths) {
        sum += l;
        s.min = std::min(s.min, double(l));
        s.max = std::max(s.max, double(l));
    }
    s.mean = sum / double(n);
    auto middle = lengths.begin() + n / 2;
    std::nth_element(lengths.begin(), middle, lengths.end());
    s.median = *middle;
    if (n % 2 == 0) s.median = 0.5 * (s.median + double(*std::max_element(lengths.begin(), middle)));
    return s;
}

bool is_degenerate_face(const Mesh& mesh, const Face& f) {
    if (!is_valid_face(f, mesh.vertex_count())) return true;
    const glm::dvec3 a(mesh.positions[f[0]]), b(mesh.positions[f[1]]), c(mesh.positions[f[2]]);
    return is_degenerate_triangle(b - a, c - b, a - c);
}

size_t count_degenerate_faces(const Mesh& mesh) {
    std::atomic<size_t> count{0};
    parallel_for_ranges(mesh.face_count(), [&](size_t first, size_t last) {
        size_t local = 0;
        for (size_t f = first; f < last; ++f) local += is_degenerate_face(mesh, mesh.faces[f]);
        count += local;
    });
    return count;
}

MeshStats compute_mesh_stats(const Mesh& mesh) {
    MeshStats s;
    s.vertices = mesh.vertex_count();
    s.faces = mesh.face_count();
    s.bounds = bounding_box(mesh);
    s.degenerate_faces = count_degenerate_faces(mesh);
    const EdgeTable edges = build_edge_table(mesh);
    s.edge_lengths = edge_length_stats(mesh, edges);
    s.topology = analyze_topology(mesh, edges);
    return s;
}

}  // namespace kappa
