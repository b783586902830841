#include "crease_vote.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace kappa {

namespace {

// A fixed 64-bit mix (splitmix64's finaliser).
uint64_t mix(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

}  // namespace

bool auto_creases_on(const EdgeBends& bends) { return bends.interior > 0 && 2 * bends.between <= bends.interior; }

namespace {

// The vote from sampled vertices' counts (interior, between edges at each).
CreaseVote vote_from(const std::vector<glm::uvec2>& counts) {
    uint64_t interior_edges = 0, between = 0;
    for (const glm::uvec2& c : counts) interior_edges += c.x, between += c.y;
    if (interior_edges == 0) return CreaseVote::Unclear;
    const double interior = double(interior_edges), p = double(between) / interior;
    // The ratio estimate's variance: n / (n - 1) sum (b_i - p i_i)^2 / I^2.
    double spread = 0;
    for (const glm::uvec2& c : counts) spread += std::pow(double(c.y) - p * double(c.x), 2);
    const double n = double(counts.size());
    const double error = std::max(std::sqrt(n / (n - 1) * spread) / interior, 0.5 / std::sqrt(interior));
    if (p + kVoteErrors * error < 0.5) return CreaseVote::On;
    if (p - kVoteErrors * error > 0.5) return CreaseVote::Off;
    return CreaseVote::Unclear;
}

}  // namespace

CreaseVote sampled_crease_vote(const Mesh& mesh, const VertexFaces& vf, size_t* vertices_looked_at) {
    const size_t nv = mesh.vertex_count();
    if (vertices_looked_at) *vertices_looked_at = 0;
    if (nv < 8 * kVoteSamples) return CreaseVote::Unclear;
    // One vertex in each run [lo, hi), increasing; every kFirstStage-th of them first.
    std::vector<uint32_t> first, rest;
    for (size_t i = 0; i < kVoteSamples; ++i) {
        const size_t lo = i * nv / kVoteSamples, hi = (i + 1) * nv / kVoteSamples;
        (i % kFirstStage == 0 ? first : rest).push_back(uint32_t(lo + mix(i) % (hi - lo)));
    }
    std::vector<glm::uvec2> counts, more;  // (interior, between) at each sampled vertex
    measure_edge_bends_at(mesh, vf, 0, first, &counts);
    if (vertices_looked_at) *vertices_looked_at = first.size();
    if (const CreaseVote vote = vote_from(counts); vote != CreaseVote::Unclear) return vote;
    measure_edge_bends_at(mesh, vf, 0, rest, &more);
    if (vertices_looked_at) *vertices_looked_at += rest.size();
    counts.insert(counts.end(), more.begin(), more.end());
    return vote_from(counts);
}

}  // namespace kappa
