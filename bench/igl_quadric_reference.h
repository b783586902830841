// A REFERENCE, for the accuracy lab only: what libigl's
// igl::principal_curvature (include/igl/principal_curvature.h; Panozzo,
// Puppo & Rocca 2010, "Efficient multi-scale curvature and crease
// estimation") computes with a ball neighbourhood (useKring = false), as its
// documentation and source describe it, written here independently (no
// libigl code; Debian 12 has no libigl package). Not part of kappa.
//
// Per vertex v, with r = radius x the mean edge length (libigl's radius,
// default 5; its mean over every face's three edges):
//   1. the ball: vertices reached from v through edges while staying within
//      Euclidean distance r of v (v included), at least 6 (the nearest
//      beyond r are added where fewer);
//   2. the normal: v's area-weighted vertex normal (libigl's default,
//      "local mode"); vertices whose own normal faces away from it are
//      dropped, if at least 6 remain;
//   3. a quadric z = a x^2 + b x y + c y^2 + d x + e y through v (no
//      constant term) fitted by unweighted least squares in v's tangent
//      frame (libigl solves by SVD; here by the normal equations, equilibrated,
//      the same solution for these well-posed 5-unknown fits);
//   4. the principal curvatures: eigenvalues, negated, of libigl's symmetric
//      2x2 matrix [[L G - M F, M E - L F], [M E - L F, N E - M F]] / (E G - F^2)
//      with E = 1 + d^2, F = d e, G = 1 + e^2, (L, M, N) = (2a, b, 2c) n_z,
//      n_z = 1 / |(-d, -e, 1)|; the eigenvectors, taken in the tangent plane,
//      are the principal directions (its sign convention: convex positive
//      against the outward normal, as kappa's).
// libigl gives no derivative of curvature: the estimate's C is empty.
#pragma once

#include "geometry/curvature/estimate.h"
#include "geometry/curvature/normal_equations.h"
#include "geometry/curvature/rings.h"
#include "geometry/curvature/tensor_frames.h"
#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace kappa::bench {

// The mean length of every face's three edges (interior edges twice), as libigl's.
inline double igl_mean_edge(const Mesh& mesh) {
    double sum = 0;
    size_t count = 0;
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            sum += glm::length(glm::dvec3(mesh.positions[f[k]]) - glm::dvec3(mesh.positions[f[(k + 1) % 3]]));
            ++count;
        }
    return count ? sum / double(count) : 0.0;
}

// Step 1: the vertices within distance r of v reached through edges, v first;
// at least 6 (the nearest reached vertices beyond r are added).
// `seen`: one mark per mesh vertex, all different from `epoch` (a per-thread scratch).
inline void igl_ball(const Mesh& mesh, const VertexAdjacency& adj, uint32_t v, double r, std::vector<uint32_t>& ball,
                     std::vector<uint32_t>& seen, uint32_t epoch) {
    const glm::dvec3 p(mesh.positions[v]);
    auto distance = [&](uint32_t q) { return glm::length(glm::dvec3(mesh.positions[q]) - p); };
    ball.assign(1, v);
    seen[v] = epoch;
    std::vector<std::pair<double, uint32_t>> beyond;
    for (size_t i = 0; i < ball.size(); ++i)
        for (uint32_t k = adj.begin(ball[i]); k < adj.end(ball[i]); ++k) {
            const uint32_t q = adj.neighbours[k];
            if (seen[q] == epoch) continue;
            seen[q] = epoch;
            const double d = distance(q);
            if (d < r) ball.push_back(q);
            else beyond.push_back({d, q});
        }
    std::sort(beyond.begin(), beyond.end());
    for (size_t i = 0; ball.size() < 6 && i < beyond.size(); ++i) ball.push_back(beyond[i].second);
}

// libigl's principal_curvature with a ball of `radius` mean edges, as
// CurvatureEstimate (normals: the area-weighted vertex normals; no C).
inline CurvatureEstimate igl_quadric_reference(const Mesh& mesh, const VertexFaces& vf, const FaceGeometry& faces,
                                               double radius = 5) {
    const size_t nv = mesh.vertex_count();
    CurvatureEstimate out = empty_estimate(nv, false);
    out.normals.assign(nv, glm::vec3(0, 0, 1));
    std::vector<glm::dvec3> normal(nv, glm::dvec3(0));
    for (size_t v = 0; v < nv; ++v) {
        for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) normal[v] += glm::dvec3(faces.area_normal(vf.corners[k] / 3));
        const double len = glm::length(normal[v]);
        normal[v] = len > 0 ? normal[v] / len : glm::dvec3(0, 0, 1);
        out.normals[v] = glm::vec3(normal[v]);
    }
    const VertexAdjacency adj = build_vertex_adjacency(mesh, vf);
    const double r = radius * igl_mean_edge(mesh);
    parallel_for_ranges(nv, [&](size_t begin, size_t end) {
        std::vector<uint32_t> ball, kept, seen(nv, 0);
        for (size_t v = begin; v < end; ++v) {
            igl_ball(mesh, adj, uint32_t(v), r, ball, seen, uint32_t(v - begin + 1));
            const glm::dvec3 n = normal[v];
            kept.clear();
            for (uint32_t q : ball)
                if (glm::dot(normal[q], n) > 0) kept.push_back(q);
            const std::vector<uint32_t>& points = kept.size() >= 6 ? kept : ball;
            glm::vec3 fu, fw;
            tangent_frame(glm::vec3(n), fu, fw);
            const glm::dvec3 u(fu), w(fw), p0(mesh.positions[v]);
            double scale = 0;  // coordinates scaled to the ball, for conditioning only
            for (uint32_t q : points) scale = std::max(scale, glm::length(glm::dvec3(mesh.positions[q]) - p0));
            if (!(scale > 0)) continue;
            NormalEquations<5> eq;
            for (uint32_t q : points) {
                const glm::dvec3 d = (glm::dvec3(mesh.positions[q]) - p0) / scale;
                const double x = glm::dot(d, u), y = glm::dot(d, w), z = glm::dot(d, n);
                eq.add({x * x, x * y, y * y, x, y}, z);
            }
            double c[5];
            if (!eq.solve(5, c, 1e-13)) continue;
            const double a = c[0] / scale, b = c[1] / scale, cc = c[2] / scale, dx = c[3], ey = c[4];
            const double E = 1 + dx * dx, F = dx * ey, G = 1 + ey * ey;
            const double nz = 1 / std::sqrt(1 + dx * dx + ey * ey);
            const double L = 2 * a * nz, M = b * nz, N = 2 * cc * nz;
            const double det = E * G - F * F;
            // libigl's symmetric matrix, negated: II in the frame (u, w).
            const double m11 = -(L * G - M * F) / det, m12 = -(M * E - L * F) / det, m22 = -(N * E - M * F) / det;
            out.tensors.tensor[v] = {float(m11), float(m12), float(m22)};
        }
    });
    return out;
}

}  // namespace kappa::bench
