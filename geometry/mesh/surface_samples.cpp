#include "surface_samples.h"

#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

// SplitMix64 (Steele et al. 2014): a small, well-mixed, portable generator.
// Each sample starts its own stream from (seed, index), so samples can be
// drawn in parallel and still not depend on the thread count.
struct SplitMix64 {
    uint64_t state;
    uint64_t next() {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }  // [0, 1)
};

SplitMix64 sample_stream(uint64_t seed, size_t index) {
    SplitMix64 mix{seed};
    SplitMix64 stream{mix.next() ^ (uint64_t(index) * 0xd1b54a32d192ed03ull)};
    stream.next();
    return stream;
}

double face_area(const Mesh& mesh, const Face& f) {
    const glm::dvec3 a(mesh.positions[f[0]]), b(mesh.positions[f[1]]), c(mesh.positions[f[2]]);
    const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
    return std::isfinite(area) ? area : 0.0;
}

// d1 at barycentric weights w: the vertices' directions, signs aligned with
// the first (principal directions are defined up to sign), averaged and
// projected on the tangent plane. Zero where the three disagree by more
// than the unweighted mean's length of 0.8 allows.
glm::vec3 interpolate_direction(const glm::vec3 d[3], const double w[3], const glm::vec3& normal) {
    glm::vec3 aligned[3] = {d[0], glm::dot(d[0], d[1]) < 0 ? -d[1] : d[1], glm::dot(d[0], d[2]) < 0 ? -d[2] : d[2]};
    if (glm::length(aligned[0] + aligned[1] + aligned[2]) < 2.4f) return glm::vec3(0);
    glm::vec3 dir = float(w[0]) * aligned[0] + float(w[1]) * aligned[1] + float(w[2]) * aligned[2];
    dir -= glm::dot(dir, normal) * normal;
    const float len = glm::length(dir);
    return len > 1e-6f ? dir / len : glm::vec3(0);
}

}  // namespace

SurfaceSamples sample_surface(const Mesh& mesh, const SurfaceFields& fields, size_t count, uint64_t seed) {
    // Cumulative areas: a uniform number r in [0, total) picks the face
    // whose interval [cumulative[f - 1], cumulative[f]) holds it, with
    // probability proportional to its area. A guide table (Chen and Asau
    // 1974) maps r to the first candidate face in O(1) on average.
    const size_t nf = mesh.face_count();
    std::vector<double> cumulative(nf);
    parallel_for(nf, [&](size_t f) { cumulative[f] = face_area(mesh, mesh.faces[f]); });
    double total = 0;
    for (double& c : cumulative) c = total += c;
    SurfaceSamples result;
    result.area = total;
    if (!(total > 0)) return result;
    std::vector<uint32_t> guide(nf);
    for (size_t k = 0, f = 0; k < nf; ++k) {
        const double r = total * double(k) / double(nf);
        while (f + 1 < nf && cumulative[f] <= r) ++f;
        guide[k] = uint32_t(f);
    }
    std::vector<SurfaceSample>& samples = result.points;
    samples.resize(count);
    parallel_for(count, [&](size_t i) {
        SplitMix64 rng = sample_stream(seed, i);
        size_t f = 0;
        for (;;) {  // rounding can land past the end or on a zero-area face: draw again
            const double u = rng.uniform(), r = u * total;
            f = guide[std::min(size_t(u * double(nf)), nf - 1)];
            while (f + 1 < nf && cumulative[f] <= r) ++f;
            if (cumulative[f] > r && cumulative[f] > (f ? cumulative[f - 1] : 0.0)) break;
        }
        // Uniform point of the triangle: (1 - sqrt(u), sqrt(u)(1 - v), sqrt(u) v).
        const double su = std::sqrt(rng.uniform()), v = rng.uniform();
        const double w[3] = {1.0 - su, su * (1.0 - v), su * v};
        const Face& face = mesh.faces[f];
        SurfaceSample& s = samples[i];
        glm::dvec3 p(0), n(0);
        glm::vec3 d[3];
        for (int k = 0; k < 3; ++k) {
            p += w[k] * glm::dvec3(mesh.positions[face[k]]);
            n += w[k] * glm::dvec3(fields.normals[face[k]]);
            d[k] = fields.d1[face[k]];
        }
        s.position = glm::vec3(p);
        const double len = glm::length(n);
        if (len > 1e-12) {
            s.normal = glm::vec3(n / len);
        } else {  // opposite vertex normals: fall back on the face's own
            const glm::vec3 e = glm::cross(mesh.positions[face[1]] - mesh.positions[face[0]],
                                           mesh.positions[face[2]] - mesh.positions[face[0]]);
            s.normal = glm::normalize(e);
        }
        s.direction = interpolate_direction(d, w, s.normal);
        s.face = uint32_t(f);
    });
    return result;
}

}  // namespace kappa
