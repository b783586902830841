// CGAL's Monge_via_jet_fitting (Cazals & Pouget 2003) at a vertex, and at
// every vertex as a kappa CurvatureEstimate: the reference of
// bench/cgal_jet.cpp (speed) and of the accuracy lab (bench/accuracy_lab.cpp,
// built with it only where CMake finds CGAL and Eigen; Debian: libcgal-dev
// libeigen3-dev). CI needs neither.
//
// The fit as CGAL's figures in issue 10: degree 4 (d_fitting), Monge
// coefficients to order 3 (d_monge: curvature and C), over the vertex's
// 2-ring with the vertex first (CGAL takes the first point as the origin),
// grown a ring at a time up to 4 where it has fewer than the 15 points a
// degree-4 fit needs. CGAL fits in the PCA frame of the points and returns
// the Monge form z = (k1 x^2 + k2 y^2) / 2 + (b0 x^3 + 3 b1 x^2 y + 3 b2 x y^2
// + b3 y^3) / 6 + ... in its frame (d1, d2, n). Oriented along kappa's
// normal (comply_wrt_given_normal), kappa's II = dN is -k and its C is -b
// in (d1, d2) (conventions.md: convex positive).
#pragma once

#include "geometry/curvature/estimate.h"
#include "geometry/curvature/rings.h"
#include "geometry/curvature/tensor_frames.h"
#include "geometry/parallel/parallel.h"

#include "tests/analytic_curvature.h"

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <vector>

namespace kappa::bench {

using CgalKernel = CGAL::Simple_cartesian<double>;
using CgalMongeFit = CGAL::Monge_via_jet_fitting<CgalKernel>;

constexpr std::size_t kCgalFitDegree = 4, kCgalMongeDegree = 3;
constexpr std::size_t kCgalPointsNeeded = (kCgalFitDegree + 1) * (kCgalFitDegree + 2) / 2;

// v's 2-ring as CGAL points, v first, grown up to 4 rings where it has fewer
// than kCgalPointsNeeded points. False: still too few (the vertex is skipped).
inline bool cgal_ring_points(const Mesh& mesh, const VertexAdjacency& adj, RingCollector& rings, uint32_t v,
                             std::vector<CgalKernel::Point_3>& points) {
    const std::vector<uint32_t>& ring = rings.collect(adj, v, 2);
    for (int k = 2; ring.size() < kCgalPointsNeeded && k < 4;) {
        const size_t before = ring.size();
        k = rings.grow(adj);
        if (ring.size() == before) break;
    }
    if (ring.size() < kCgalPointsNeeded) return false;
    points.clear();
    for (uint32_t q : ring) {
        const glm::vec3& p = mesh.positions[q];
        points.emplace_back(p.x, p.y, p.z);
    }
    return true;
}

// CGAL's fit at every vertex; normals: kappa's (they orient the Monge form
// only). Skipped vertices keep a zero estimate.
inline CurvatureEstimate cgal_jet_estimate(const Mesh& mesh, const VertexFaces& vf,
                                           const std::vector<glm::vec3>& normals) {
    const size_t nv = mesh.vertex_count();
    const VertexAdjacency adj = build_vertex_adjacency(mesh, vf);
    CurvatureEstimate out = empty_estimate(nv, true);
    out.normals = normals;
    parallel_for_ranges(nv, [&](size_t begin, size_t end) {
        RingCollector rings(nv);
        std::vector<CgalKernel::Point_3> points;
        for (size_t v = begin; v < end; ++v) {
            if (!cgal_ring_points(mesh, adj, rings, uint32_t(v), points)) continue;
            CgalMongeFit fit;
            CgalMongeFit::Monge_form m = fit(points.begin(), points.end(), kCgalFitDegree, kCgalMongeDegree);
            const glm::vec3& kn = normals[v];
            m.comply_wrt_given_normal(CgalKernel::Vector_3(kn.x, kn.y, kn.z));
            auto vec = [](const CgalKernel::Vector_3& x) { return glm::dvec3(x.x(), x.y(), x.z()); };
            const glm::dvec3 d1 = vec(m.maximal_principal_direction()), d2 = vec(m.minimal_principal_direction());
            const glm::dvec3 n = glm::normalize(vec(m.normal_direction()));
            const double k1 = m.principal_curvatures(0), k2 = m.principal_curvatures(1);
            glm::vec3 fu, fw;
            tangent_frame(glm::vec3(n), fu, fw);
            const glm::dvec3 u(fu), w(fw);
            const glm::dmat3 S = -k1 * test::outer(d1, d1) - k2 * test::outer(d2, d2);
            out.normals[v] = glm::vec3(n);
            out.tensors.tensor[v] = {float(glm::dot(u, S * u)), float(glm::dot(u, S * w)), float(glm::dot(w, S * w))};
            const glm::dvec4 b(m.third_order_coefficients(0), m.third_order_coefficients(1),
                               m.third_order_coefficients(2), m.third_order_coefficients(3));
            out.dcurv_uv[v] = glm::vec4(test::dcurv_in_tangent_frame(-b, d1, d2, n));
        }
    });
    return out;
}

}  // namespace kappa::bench
