// Sharp edges ("creases") and the mesh split along them.
//
// An edge is a crease when it is shared by exactly two faces whose normals
// turn by more than `angle_deg` (the dihedral angle's supplement: 0 for a
// flat pair, 90 for a cube's edge). CAD parts, low-poly models and
// architecture have them; on them the per-vertex estimate of Rusinkiewicz
// 2004 would average normals and curvature across the edge (pillowed
// shading, stray lines parallel to the edge). Splitting the mesh there gives
// each smooth side its own copies of the crease's vertices, so normals,
// curvature, C and the scale space's clusters (which join only along mesh
// edges) stay on their side.
#pragma once

#include "mesh.h"
#include "vertex_faces.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace kappa {

// The unit normal of a face (counter-clockwise from outside); zero where
// the face is degenerate or not finite. The two faces of a crease bend by
// the angle between theirs.
glm::vec3 face_normal(const Mesh& mesh, const Face& f);

// The crease edges as vertex pairs (v0 < v1, sorted). angle_deg <= 0: none.
std::vector<glm::uvec2> find_creases(const Mesh& mesh, float angle_deg);

// `--crease-angle auto`, the default: 40 degrees on meshes made of flat and
// sharp pieces, none on others. No threshold alone tells a CAD edge from a
// scan: noisy or coarse smooth meshes have many edges turning by more than
// 40 degrees too (bunny.ply 550, dragon-50k 12262, spot 73; fandisk 710).
// What tells them apart is how their faces meet: on CAD parts most interior
// edges are flat (under 0.5 degrees) or sharp (over 40), with few between
// (fandisk 15%, a cube 0%, a cylinder with flat caps 17%), while on smooth
// meshes most are between (bunny-1M 66%, bunny.ply 89%, spot and
// dragon-50k about 90%). Creases are on when at most half are between.
constexpr float kAutoCreaseAngle = 40.0f;
float auto_crease_angle(const Mesh& mesh);  // kAutoCreaseAngle or 0

// The angle a `--crease-angle` setting resolves to (< 0: auto, as
// auto_crease_angle; 0: off) and the creases at it (as find_creases), from
// one look at the edges (edge_bends.h) instead of one for each.
struct ResolvedCreases {
    float angle = 0;
    std::vector<glm::uvec2> creases;
};
ResolvedCreases resolve_creases(const Mesh& mesh, float setting);
// The same with the mesh's vertex-face rows given (build_vertex_faces).
ResolvedCreases resolve_creases(const Mesh& mesh, const VertexFaces& vf, float setting);

struct SplitMesh {
    Mesh mesh;                            // the input with crease vertices duplicated per side
    std::vector<uint32_t> original;       // for each vertex of `mesh`, the input vertex it copies
    std::vector<glm::uvec2> creases;      // crease edges, in `mesh`'s vertex numbers (one side's copy)
    std::vector<glm::uvec2> crease_faces; // the two faces along each crease
};

// Splits the mesh along `creases` (from find_creases): around each vertex,
// the faces that reach each other across non-crease edges form one side and
// share one copy of the vertex. The first side keeps the vertex's number;
// extra copies are appended. Faces keep their order. Deterministic. Takes
// the mesh by value: callers done with theirs move it in. Costs one pass
// over the faces plus work around the crease vertices.
// With `vf` (the input's vertex-face rows), they are made the split mesh's,
// as build_vertex_faces would build them: the rows of the crease vertices
// lose the corners that moved to copies, which get rows of their own.
SplitMesh split_at_creases(Mesh mesh, const std::vector<glm::uvec2>& creases, VertexFaces* vf = nullptr);

}  // namespace kappa
