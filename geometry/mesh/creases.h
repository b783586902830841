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

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <cmath>

#include <cstdint>
#include <optional>
#include <vector>

namespace kappa {

// The unit normal of a face (counter-clockwise from outside); zero where
// the face is degenerate or not finite. The two faces of a crease bend by
// the angle between theirs.
inline glm::vec3 face_cross(const Mesh& mesh, const Face& f) {  // the normal before it is made unit
    return glm::cross(mesh.positions[f[1]] - mesh.positions[f[0]], mesh.positions[f[2]] - mesh.positions[f[0]]);
}
inline glm::vec3 face_normal(const Mesh& mesh, const Face& f) {
    const glm::vec3 c = face_cross(mesh, f);
    const float len = glm::length(c);
    return len > 0 && std::isfinite(len) ? c / len : glm::vec3(0.0f);
}

// The crease edges as vertex pairs (v0 < v1, sorted). angle_deg <= 0: none.
// Looks only around the vertices where an edge may turn by more than the
// angle (crease_candidates.h), then exactly as edge_bends.h.
std::vector<glm::uvec2> find_creases(const Mesh& mesh, float angle_deg);
// The same with the mesh's vertex-face rows given and its candidates found
// (crease_candidates.h, or in face_survey.h's pass).
std::vector<glm::uvec2> creases_around(const Mesh& mesh, const VertexFaces& vf, float angle_deg,
                                      const std::vector<uint32_t>& candidates);

// `--crease-angle auto`, the default: 40 degrees on meshes made of flat and
// sharp pieces, none on others. No threshold alone tells a CAD edge from a
// scan: noisy or coarse smooth meshes have many edges turning by more than
// 40 degrees too (bunny.ply 550, dragon-50k 12262, spot 73; fandisk 710).
// What tells them apart is how their faces meet: on CAD parts most interior
// edges are flat (under 0.5 degrees) or sharp (over 40), with few between
// (fandisk 15%, a cube 0%, a cylinder with flat caps 17%), while on smooth
// meshes most are between (bunny-1M 66%, bunny.ply 89%, spot and
// dragon-50k about 90%). Creases are on when at most half are between: on
// big meshes far from half, as a sample of their edges tells (crease_vote.h).
constexpr float kAutoCreaseAngle = 40.0f;
float auto_crease_angle(const Mesh& mesh);  // kAutoCreaseAngle or 0

// The angle a `--crease-angle` setting resolves to (< 0: auto, as
// auto_crease_angle; 0: off) when no whole count of the edges is needed:
// the setting itself, or auto's from the sampled vote; nullopt when the
// sample cannot tell (then resolve_creases counts every edge).
std::optional<float> sampled_crease_angle(const Mesh& mesh, const VertexFaces& vf, float setting);

// The angle a setting resolves to and the creases at it (as find_creases),
// looking at every edge at most once.
struct ResolvedCreases {
    float angle = 0;
    std::vector<glm::uvec2> creases;
};
ResolvedCreases resolve_creases(const Mesh& mesh, float setting);
// The same with the mesh's vertex-face rows given (build_vertex_faces);
// find = false: the angle alone.
ResolvedCreases resolve_creases(const Mesh& mesh, const VertexFaces& vf, float setting, bool find = true);

struct SplitMesh {
    Mesh mesh;                            // the input with crease vertices duplicated per side
    std::vector<uint32_t> copied_from;    // for each copy (the vertices from first_copy() on), its input vertex
    std::vector<glm::uvec2> creases;      // crease edges, in `mesh`'s vertex numbers (one side's copy)
    std::vector<glm::uvec2> crease_faces; // the two faces along each crease

    size_t first_copy() const { return mesh.vertex_count() - copied_from.size(); }
    // The input vertex that vertex v of `mesh` is, or copies.
    uint32_t original(size_t v) const { return v < first_copy() ? uint32_t(v) : copied_from[v - first_copy()]; }
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
