#include "cluster_bounds.h"

#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kappa {

namespace {

// The unit vector along v; false when v is zero or not finite. Scales by the
// largest component first where |v|^2 would underflow or overflow.
bool unit_direction(const glm::vec3& v, glm::vec3& unit) {
    const float len2 = glm::dot(v, v);
    if (len2 > 1e-30f && len2 < 1e30f) {
        unit = v / std::sqrt(len2);
        return true;
    }
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
    const float m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(m > 0)) return false;
    const glm::vec3 u = v / m;
    unit = u / glm::length(u);
    return true;
}

}  // namespace

namespace {

// The cone around `dirs` (unit normals) in b; left "all directions" when they
// do not fit in one (or all_directions).
void fit_cone(const std::vector<glm::vec3>& dirs, bool all_directions, ClusterBounds& b) {
    // The cone: axis along the sum of the unit normals; the half-angle from
    // the largest chord |n - axis| = 2 sin(angle / 2), which unlike
    // dot(n, axis) stays accurate for the small angles that matter.
    glm::vec3 sum(0.0f);
    for (const glm::vec3& n : dirs) sum += n;
    const float sum_len = glm::length(sum);
    if (all_directions || dirs.empty() || !(sum_len > 1e-6f * float(dirs.size())) || !std::isfinite(sum_len))
        return;  // the default: all directions
    b.axis = sum / sum_len;
    float chord2 = 0;
    for (const glm::vec3& n : dirs) {
        const glm::vec3 e = n - b.axis;
        chord2 = std::max(chord2, glm::dot(e, e));
    }
    const double half_angle = 2.0 * std::asin(std::min(1.0, 0.5 * std::sqrt(double(chord2))));
    b.cos_angle = float(std::cos(half_angle));
    b.sin_angle = float(std::sin(half_angle));
}

}  // namespace

std::vector<std::vector<ClusterBounds>> compute_cluster_bounds_for_sets(
    const Mesh& mesh, const std::vector<const std::vector<glm::vec3>*>& normal_sets, const FaceClusters& clusters) {
    constexpr uint32_t none = std::numeric_limits<uint32_t>::max();
    std::vector<std::vector<ClusterBounds>> out(normal_sets.size(), std::vector<ClusterBounds>(clusters.size()));
    // Clusters are independent: ranges of them in parallel (one a thread), each with its own scratch.
    // The vertices, face normals and sphere of a cluster are found once for all normal sets.
    parallel_for_ranges(clusters.size(), [&](size_t first, size_t end) {
        std::vector<uint32_t> seen(mesh.vertex_count(), none);  // seen[v] == c: v already listed for cluster c
        std::vector<uint32_t> verts;                            // the current cluster's distinct vertices
        std::vector<glm::vec3> dirs;                            // its unit normals (faces, then vertices)

        for (size_t c = first; c < end; ++c) {
            verts.clear();
            dirs.clear();
            for (uint32_t i = clusters.cluster_start[c]; i < clusters.cluster_start[c + 1]; ++i) {
                const Face& f = mesh.faces[clusters.face_order[i]];
                for (int j = 0; j < 3; ++j)
                    if (seen[f[j]] != uint32_t(c)) {
                        seen[f[j]] = uint32_t(c);
                        verts.push_back(f[j]);
                    }
                const glm::vec3 p0 = mesh.positions[f[0]];
                glm::vec3 n;
                if (unit_direction(glm::cross(mesh.positions[f[1]] - p0, mesh.positions[f[2]] - p0), n))
                    dirs.push_back(n);
            }
            const size_t face_dirs = dirs.size();

            glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
            glm::vec3 not_finite(0.0f);  // p - p: stays zero unless some p is inf or NaN (which min/max would skip)
            for (uint32_t v : verts) {
                const glm::vec3 p = mesh.positions[v];
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
                not_finite += p - p;
            }
            ClusterBounds sphere;
            if (!(not_finite == glm::vec3(0.0f))) {
                sphere.radius = std::numeric_limits<float>::infinity();  // and all directions: never culled
                for (auto& set : out) set[c] = sphere;
                continue;
            }
            sphere.center = 0.5f * (lo + hi);
            float r2 = 0;
            for (uint32_t v : verts) {
                const glm::vec3 e = mesh.positions[v] - sphere.center;
                r2 = std::max(r2, glm::dot(e, e));
            }
            sphere.radius = std::sqrt(r2);

            for (size_t s = 0; s < normal_sets.size(); ++s) {
                const std::vector<glm::vec3>& vertex_normals = *normal_sets[s];
                dirs.resize(face_dirs);
                bool all_directions = false;
                for (uint32_t v : verts) {
                    glm::vec3 n;
                    if (unit_direction(vertex_normals[v], n)) dirs.push_back(n);
                    else all_directions = true;
                }
                ClusterBounds& b = out[s][c];
                b = sphere;
                fit_cone(dirs, all_directions, b);
            }
        }
    }, 64);
    return out;
}

std::vector<ClusterBounds> compute_cluster_bounds(const Mesh& mesh, const std::vector<glm::vec3>& vertex_normals,
                                                  const FaceClusters& clusters) {
    return std::move(compute_cluster_bounds_for_sets(mesh, {&vertex_normals}, clusters).front());
}

// Why the test is conservative. Let d = eye - center, beta = angle(d, axis),
// alpha the cone half-angle. For a unit normal n in the cone, angle(n, d) lies
// in [max(beta - alpha, 0), min(beta + alpha, pi)] (triangle inequality on the
// unit sphere), and for |p - center| <= r, dot(n, eye - p) = dot(n, d) + dot(n, center - p)
// with |dot(n, center - p)| <= r. Hence
//   |d| cos(min(beta + alpha, pi)) - r  <=  dot(n, eye - p)  <=  |d| cos(max(beta - alpha, 0)) + r.
// Both bounds can only have the sign we want when alpha < pi/2. Then, with
// a = dot(d, axis) = |d| cos(beta) and s = |cross(d, axis)| = |d| sin(beta):
//   Front needs beta + alpha < pi/2, where |d| cos(beta + alpha) = a cos(alpha) - s sin(alpha);
//   Back needs beta - alpha > pi/2, where |d| cos(beta - alpha) = a cos(alpha) + s sin(alpha).
// (These closed forms avoid acos, which loses half the digits near beta = 0.)
// Non-unit normals do not matter: only the sign of dot(n, eye - p) is asked for.
Facing classify_facing(const ClusterBounds& b, const glm::vec3& eye) {
    if (!(b.cos_angle > 0)) return Facing::Mixed;
    const glm::vec3 d = eye - b.center;
    const float a = glm::dot(d, b.axis), s = glm::length(glm::cross(d, b.axis));
    // Float rounding in d, a, s, the radius and the cone angle: each is below a
    // few 1e-7 of these magnitudes (|center| enters through eye - p and p - center).
    const float margin = 1e-5f * (glm::length(d) + b.radius + glm::length(b.center));
    if (a * b.cos_angle - s * b.sin_angle - b.radius > margin) return Facing::Front;
    if (a * b.cos_angle + s * b.sin_angle + b.radius < -margin) return Facing::Back;
    return Facing::Mixed;  // also when anything is NaN
}

}  // namespace kappa
