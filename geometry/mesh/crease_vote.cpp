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

CreaseVote sampled_crease_vote(const Mesh& mesh, const VertexFaces& vf) {
    const size_t nv = mesh.vertex_count();
    if (nv < 8 * kVoteSamples) return CreaseVote::Unclear;
    std::vector<uint32_t> sample(kVoteSamples);
    for (size_t i = 0; i < kVoteSamples; ++i) {  // one vertex in each run [lo, hi), increasing
        const size_t lo = i * nv / kVoteSamples, hi = (i + 1) * nv / kVoteSamples;
        sample[i] = uint32_t(lo + mix(i) % (hi - lo));
    }
    std::vector<glm::uvec2> counts;  // (interior, between) at each sampled vertex
    const EdgeBends bends = measure_edge_bends_at(mesh, vf, 0, sample, &counts);
    if (bends.interior == 0) return CreaseVote::Unclear;
    const double interior = double(bends.interior), p = double(bends.between) / interior;
    // The ratio estimate's variance: n / (n - 1) sum (b_i - p i_i)^2 / I^2.
    double spread = 0;
    for (const glm::uvec2& c : counts) spread += std::pow(double(c.y) - p * double(c.x), 2);
    const double n = double(counts.size());
    const double error = std::max(std::sqrt(n / (n - 1) * spread) / interior, 0.5 / std::sqrt(interior));
    if (p + kVoteErrors * error < 0.5) return CreaseVote::On;
    if (p - kVoteErrors * error > 0.5) return CreaseVote::Off;
    return CreaseVote::Unclear;
}

}  // namespace kappa
