// Everything `kappa info` reports about a mesh that does not need curvature:
// counts, bounding box, edge lengths, degenerate faces and the topology of
// mesh_topology.h.
#pragma once

#include "edge_table.h"
#include "mesh.h"
#include "mesh_topology.h"

#include <glm/vec3.hpp>

namespace kappa {

// Axis-aligned bounds of all vertex positions (isolated vertices included);
// min = max = 0 for a mesh without vertices.
struct BoundingBox {
    glm::vec3 min{0.0f}, max{0.0f};
    glm::vec3 size() const { return max - min; }
    glm::vec3 center() const { return 0.5f * (min + max); }
};

BoundingBox bounding_box(const Mesh& mesh);

// Lengths of the distinct edges of the edge table (all zero when there are
// none). The median of an even count is the mean of the two middle values.
struct EdgeLengthStats {
    double min = 0, mean = 0, median = 0, max = 0;
};

EdgeLengthStats edge_length_stats(const Mesh& mesh, const EdgeTable& edges);

// Faces that repeat a vertex index, use an index out of range, or have
// (numerically) zero area as defined by is_degenerate_triangle (degenerate.h).
bool is_degenerate_face(const Mesh& mesh, const Face& face);
size_t count_degenerate_faces(const Mesh& mesh);

struct MeshStats {
    size_t vertices = 0, faces = 0;
    BoundingBox bounds;
    EdgeLengthStats edge_lengths;
    size_t degenerate_faces = 0;
    Topology topology;
};

MeshStats compute_mesh_stats(const Mesh& mesh);

}  // namespace kappa
