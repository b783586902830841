// `--crease-angle auto` (creases.h, auto_crease_angle) decided from a sample
// of the edges when the sample leaves no doubt: creases are on when at most
// half of the interior edges turn between 0.5 and kAutoCreaseAngle degrees,
// and on a big mesh far from that half a few thousand vertices tell.
//
// The sample: one vertex drawn in each of kVoteSamples equal runs of vertex
// numbers (a fixed hash picks it, so the sample is always the same), and at
// each the edges (v, w), w > v, as the whole count meets them (edge_bends.h).
// Every kFirstStage-th sampled vertex is looked at first: where those alone
// give a vote that stands, it is the vote (most big meshes are far from 1/2;
// the whole sample, kFirstStage times as many vertices, would put p closer
// still to where they put it); otherwise the whole sample votes.
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
constexpr size_t kFirstStage = 8;

// The vote from the whole count (what the sample stands for).
bool auto_creases_on(const EdgeBends& bends);
// The vote from a sample: Unclear when the whole count must decide.
// vertices_looked_at, where given: how many sampled vertices it took (kVoteSamples / kFirstStage or all).
CreaseVote sampled_crease_vote(const Mesh& mesh, const VertexFaces& vf, size_t* vertices_looked_at = nullptr);

}  // namespace kappa
