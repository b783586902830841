#include "orientation.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <utility>

namespace kappa {

namespace {

// Six times the signed and unsigned volumes of the tetrahedra (centroid, face).
std::pair<double, double> volumes(const Mesh& mesh) {
    if (mesh.positions.empty() || mesh.faces.empty()) return {0, 0};
    glm::dvec3 centroid(0.0);
    for (const glm::vec3& p : mesh.positions) centroid += glm::dvec3(p);
    centroid /= double(mesh.positions.size());
    double signed_sum = 0, unsigned_sum = 0;
    for (const Face& f : mesh.faces) {
        if (f[0] >= mesh.positions.size() || f[1] >= mesh.positions.size() || f[2] >= mesh.positions.size()) continue;
        const glm::dvec3 a = glm::dvec3(mesh.positions[f[0]]) - centroid, b = glm::dvec3(mesh.positions[f[1]]) - centroid,
                         c = glm::dvec3(mesh.positions[f[2]]) - centroid;
        const double v = glm::dot(a, glm::cross(b, c));  // 6 x the tetrahedron's signed volume
        if (!std::isfinite(v)) continue;
        signed_sum += v;
        unsigned_sum += std::fabs(v);
    }
    return {signed_sum, unsigned_sum};
}

}  // namespace

bool is_inside_out(const Mesh& mesh) {
    const auto [signed_sum, unsigned_sum] = volumes(mesh);
    return unsigned_sum > 0 && signed_sum < -0.5 * unsigned_sum;
}

bool is_outside_out(const Mesh& mesh) {
    const auto [signed_sum, unsigned_sum] = volumes(mesh);
    return unsigned_sum > 0 && signed_sum > 0.5 * unsigned_sum;
}

void flip_faces(Mesh& mesh) {
    for (Face& f : mesh.faces) std::swap(f[1], f[2]);
}

}  // namespace kappa
