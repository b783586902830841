// Per-cluster bounds for view culling: a sphere around the cluster's vertices
// and a cone around its normals. A cluster seen entirely from the front (or
// entirely from behind) has n.v of one sign everywhere, so it cannot contain
// an occluding contour (a zero of n.v with n interpolated over each triangle,
// v = eye - p) and the contour pass can skip it.
#pragma once

#include "face_clusters.h"
#include "geometry/mesh/mesh.h"

#include <glm/vec3.hpp>

#include <vector>

namespace kappa {

// Per cluster: a bounding sphere of its vertices and a cone bounding its normals.
struct ClusterBounds {
    glm::vec3 center{0};
    float radius = 0;                     // every vertex of the cluster's faces lies within
    glm::vec3 axis{0, 0, 1};              // unit
    float cos_angle = -1, sin_angle = 0;  // half-angle of the cone; cos_angle = -1: all directions (never culled)
};

// Cone over: the given per-vertex normals of all vertices of the cluster's
// faces (their directions: they need not be unit), AND the unit normals of its
// non-degenerate faces, face normal = normalize(cross(p1 - p0, p2 - p0)) in
// float; only faces whose cross product is zero or not finite are skipped (so
// every face whose normalize() is finite is included). A zero or non-finite
// vertex normal makes the cone "all directions".
// Sphere: centre of the axis-aligned bounding box, radius the largest distance to it.
// A cluster with an infinite or NaN vertex position gets radius = infinity
// and the "all directions" cone (never culled).
//
// Input:  mesh, vertex_normals (size V), clusters from cluster_faces(mesh).
// Output: one ClusterBounds per cluster. O(F), clusters in parallel.
std::vector<ClusterBounds> compute_cluster_bounds(const Mesh& mesh, const std::vector<glm::vec3>& vertex_normals,
                                                  const FaceClusters& clusters);
// The same for several sets of vertex normals at once (one result per set, in
// order): the clusters' vertices, face normals and spheres are found once.
std::vector<std::vector<ClusterBounds>> compute_cluster_bounds_for_sets(
    const Mesh& mesh, const std::vector<const std::vector<glm::vec3>*>& normal_sets, const FaceClusters& clusters);

enum class Facing { Front, Back, Mixed };

// Conservative classification for an eye point (perspective camera, model coordinates):
//   Front: for every vertex p of the cluster with normal n, dot(n, eye - p) > 0, and every face normal likewise;
//   Back:  all of them < 0;
//   Mixed: anything else (also whenever unsure, e.g. non-finite bounds or eye).
// Never says Front or Back wrongly (a safety margin covers float rounding).
Facing classify_facing(const ClusterBounds& bounds, const glm::vec3& eye);

}  // namespace kappa
