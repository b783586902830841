// CSV output of the per-vertex fields (conventions.md, `kappa curvature`).
#pragma once

#include "geometry/mesh/mesh.h"
#include "../surface_fields.h"
#include "io_errors.h"

#include <string>

namespace kappa {

// Writes the header x,y,z,nx,ny,nz,k1,k2,d1x,d1y,d1z,d2x,d2y,d2z,a,b,c,d then
// one row per input vertex, in input order, each value as printf("%.9g")
// (enough digits to read back every float exactly). Throws MeshWriteError.
void write_csv(const std::string& path, const Mesh& mesh, const SurfaceFields& fields);

}  // namespace kappa
