// `--crease-angle auto` (creases.h, auto_crease_angle) decided from a sample
// of the edges when the sample leaves no doubt: creases are on when at most
// half of the interior edges turn between 0.5 and kAutoCreaseAngle degrees,
// and on a big mesh far from that half a few thousand vertices tell.
//
// The sample: one vertex drawn in each of kVoteSamples equal runs of vertex
// numbers (a fixed hash picks it, so the sample is always the same), and at
// each the edges (v, w), w > v, as the whole count meets them (edge_bends.h).
// Their share p of bent edges is a ratio estimate; its standard error comes
// from the spread of the vertices' own shares (edges at one vertex are not
// independent draws), never under that of independent edges at 1/2. The
// vote stands when p is kVoteErrors standard errors or more from 1/2;
// otherwise, and on meshes of fewer than 8 kVoteSamples vertices, the
// caller counts every edge.
#pragma once

#include "edge_bends.h"
#include "mesh.h"
#include "vertex_faces.h"

#include <cstddef>

namespace kappa {

enum class CreaseVote { On, Off, Unclear };

constexpr size_t kVoteSamples = 32768;
constexpr double kVoteErrors = 8;

// The vote from the whole count (what the sample stands for).
bool auto_creases_on(const EdgeBends& bends);
// The vote from a sample: Unclear when the whole count must decide.
CreaseVote sampled_crease_vote(const Mesh& mesh, const VertexFaces& vf);

}  // namespace kappa
