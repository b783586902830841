#include "noise_level.h"

#include "geometry/parallel/parallel.h"
#include "geometry/curvature/normal_equations.h"
#include "geometry/curvature/tensor_frames.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace kappa {

namespace {

constexpr int kCoefficients = 10;  // 1, x, y, x^2, xy, y^2, x^3, x^2 y, x y^2, y^3
constexpr size_t kTargetSamples = 16384;

// Neighbours of v through its faces, appended to out (with repeats).
void append_neighbours(const Mesh& mesh, const VertexFaces& vf, uint32_t v, std::vector<uint32_t>& out) {
    for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
        const uint32_t c = vf.corners[k];
        const Face& f = mesh.faces[c / 3];
        out.push_back(f[(c % 3 + 1) % 3]);
        out.push_back(f[(c % 3 + 2) % 3]);
    }
}

void monomials(double x, double y, double (&m)[kCoefficients]) {
    m[0] = 1;
    m[1] = x;
    m[2] = y;
    m[3] = x * x;
    m[4] = x * y;
    m[5] = y * y;
    m[6] = x * x * x;
    m[7] = x * x * y;
    m[8] = x * y * y;
    m[9] = y * y * y;
}

// sigma^2 estimate of vertex v scaled to be median-unbiased (see the
// header); negative when v is skipped.
double vertex_noise_variance(const Mesh& mesh, const VertexFaces& vf, const glm::vec3& normal, uint32_t v,
                             std::vector<uint32_t>& ring, std::vector<uint32_t>& ring2) {
    if (normal == glm::vec3(0.0f)) return -1;
    ring.clear();
    append_neighbours(mesh, vf, v, ring);
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    ring2.assign(1, v);
    for (uint32_t w : ring) {
        ring2.push_back(w);
        append_neighbours(mesh, vf, w, ring2);
    }
    std::sort(ring2.begin(), ring2.end());
    ring2.erase(std::unique(ring2.begin(), ring2.end()), ring2.end());
    const int n = int(ring2.size());
    if (n < kCoefficients + 4) return -1;

    glm::vec3 u, w;
    tangent_frame(glm::normalize(normal), u, w);
    const glm::dvec3 p0(mesh.positions[v]), du(u), dw(w), dn(glm::normalize(normal));
    // Tangent coordinates are scaled by the RMS distance for conditioning.
    double r2 = 0;
    for (uint32_t j : ring2) {
        const glm::dvec3 d = glm::dvec3(mesh.positions[j]) - p0;
        r2 += glm::dot(d, d);
    }
    if (!(r2 > 0)) return -1;
    const double inv_scale = 1.0 / std::sqrt(r2 / n);

    NormalEquations<kCoefficients> eq;
    double m[kCoefficients];
    for (uint32_t j : ring2) {
        const glm::dvec3 d = glm::dvec3(mesh.positions[j]) - p0;
        monomials(glm::dot(d, du) * inv_scale, glm::dot(d, dw) * inv_scale, m);
        eq.add(m, glm::dot(d, dn));
    }
    double coef[kCoefficients];
    if (!eq.solve(kCoefficients, coef, 1e-9)) return -1;
    // Residuals computed explicitly: z.z - b.x would lose the digits of a
    // tiny noise against the surface's height variation.
    double rss = 0;
    for (uint32_t j : ring2) {
        const glm::dvec3 d = glm::dvec3(mesh.positions[j]) - p0;
        monomials(glm::dot(d, du) * inv_scale, glm::dot(d, dw) * inv_scale, m);
        double z = glm::dot(d, dn);
        for (int r = 0; r < kCoefficients; ++r) z -= coef[r] * m[r];
        rss += z * z;
    }
    const double k = double(n - kCoefficients);
    const double median_factor = std::pow(1.0 - 2.0 / (9.0 * k), 3.0);  // Wilson-Hilferty
    return rss / (k * median_factor);
}

double median_of(std::vector<double>& values) {
    if (values.empty()) return 0;
    const size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    const double hi = values[mid];
    if (values.size() % 2) return hi;
    return 0.5 * (hi + *std::max_element(values.begin(), values.begin() + mid));
}

}  // namespace

float sampled_median_edge(const Mesh& mesh, const VertexFaces& vf) {
    const size_t nv = mesh.vertex_count();
    if (nv == 0) return 0;
    const size_t stride = (nv + kTargetSamples - 1) / kTargetSamples;
    const size_t ns = (nv + stride - 1) / stride;
    // Over the edges from each sampled vertex to its neighbours.
    std::vector<double> lengths;
    std::vector<uint32_t> ring;
    for (size_t s = 0; s < ns; ++s) {
        const uint32_t v = uint32_t(s * stride);
        ring.clear();
        append_neighbours(mesh, vf, v, ring);
        std::sort(ring.begin(), ring.end());
        ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
        for (uint32_t w : ring)
            if (w != v) lengths.push_back(glm::length(glm::dvec3(mesh.positions[w]) - glm::dvec3(mesh.positions[v])));
    }
    return float(median_of(lengths));
}

NoiseLevel estimate_noise_level(const Mesh& mesh, const VertexFaces& vf, const std::vector<glm::vec3>& normals) {
    NoiseLevel out;
    const size_t nv = mesh.vertex_count();
    if (nv == 0) return out;
    const size_t stride = (nv + kTargetSamples - 1) / kTargetSamples;
    const size_t ns = (nv + stride - 1) / stride;
    std::vector<double> variance(ns, -1.0);
    parallel_for_ranges(ns, [&](size_t first, size_t last) {
        std::vector<uint32_t> ring, ring2;
        for (size_t s = first; s < last; ++s) {
            const uint32_t v = uint32_t(s * stride);
            variance[s] = vertex_noise_variance(mesh, vf, normals[v], v, ring, ring2);
        }
    }, 256);

    out.median_edge = sampled_median_edge(mesh, vf);

    std::vector<double> valid;
    valid.reserve(ns);
    for (double x : variance)
        if (x >= 0) valid.push_back(x);
    out.samples = valid.size();
    out.sigma = float(std::sqrt(median_of(valid)));
    out.relative = out.median_edge > 0 ? out.sigma / out.median_edge : 0.0f;
    return out;
}

}  // namespace kappa
