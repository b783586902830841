// The per-vertex columns written by the PLY and CSV writers, in the order
// fixed by conventions.md: position, normal, principal curvatures and
// directions, derivative of curvature (a, b, c, d).
#pragma once

#include "geometry/mesh/mesh.h"
#include "../surface_fields.h"

#include <cstdint>
#include <string>

namespace kappa::io {

constexpr size_t kFieldColumnCount = 18;
extern const char* const kFieldColumnNames[kFieldColumnCount];

// Throws MeshWriteError "PATH: ..." unless every field the writers use has
// one entry per vertex (flags may be empty: written as 0).
void check_fields_match(const std::string& path, const Mesh& mesh, const SurfaceFields& fields);

// The 18 column values of vertex i.
inline void field_row(const Mesh& mesh, const SurfaceFields& f, size_t i, float out[kFieldColumnCount]) {
    const glm::vec3 &p = mesh.positions[i], &n = f.normals[i], &d1 = f.d1[i], &d2 = f.d2[i];
    const glm::vec4& c = f.dcurv[i];
    const float row[kFieldColumnCount] = {p.x,  p.y,  p.z,  n.x,  n.y,  n.z,  f.k1[i], f.k2[i], d1.x,
                                          d1.y, d1.z, d2.x, d2.y, d2.z, c[0], c[1],    c[2],    c[3]};
    for (size_t k = 0; k < kFieldColumnCount; ++k) out[k] = row[k];
}

inline uint8_t field_flags(const SurfaceFields& f, size_t i) { return f.flags.empty() ? 0 : f.flags[i]; }

}  // namespace kappa::io
