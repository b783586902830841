// View-dependent line extraction on the CPU (geometry/lines): chaining, and
// lines where the mathematics puts them: a sphere's contour circle, an open
// square's boundary, a cube's visible edges.
#include <catch2/catch.hpp>

#include "test_shapes.h"

#include "geometry/mesh/creases.h"
#include "geometry/lines/chain.h"
#include "geometry/lines/line_extraction.h"
#include "geometry/lines/view_ridges.h"
#include "geometry/parallel/parallel.h"
#include "geometry/mesh/primitives.h"
#include "geometry/surface_analysis.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace kappa;

namespace {

LineSegment seg(glm::vec3 a, glm::vec3 b, float sa = 1, float sb = 1) { return {a, b, sa, sb, sa, sb, 0.1f}; }

ExtractedLines lines_of(const Mesh& mesh, const SurfaceFields& fields, glm::vec3 eye, LineExtractionOptions o,
                        const std::vector<CreaseEdge>& creases = {}) {
    const ViewQuantities q = compute_view_quantities(mesh, fields, {}, eye, 1.0f);
    return extract_lines(mesh, fields, q, eye, creases, o);
}

}  // namespace

TEST_CASE("chain_segments joins segments that share end points into paths", "[lines]") {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0), e(2, 0, 0);
    SECTION("a square given in any order and orientation is one closed loop") {
        const std::vector<Polyline> loop = chain_segments({seg(c, b), seg(a, b), seg(d, a), seg(c, d)});
        REQUIRE(loop.size() == 1);
        CHECK(loop[0].points.size() == 5);
        CHECK(loop[0].closed());
    }
    SECTION("an open path comes out whole, from one end to the other, with its strengths") {
        const std::vector<Polyline> path = chain_segments({seg(b, c, 0.5f, 0.25f), seg(b, a, 0.5f, 1.0f), seg(d, c, 0.75f, 0.25f)});
        REQUIRE(path.size() == 1);
        REQUIRE(path[0].points.size() == 4);
        CHECK(!path[0].closed());
        const bool forward = path[0].points.front() == a;
        CHECK((forward ? path[0].points.back() : path[0].points.front()) == d);
        std::vector<float> s = path[0].strength, o = path[0].opacity;
        if (!forward) std::reverse(s.begin(), s.end()), std::reverse(o.begin(), o.end());
        CHECK(s == std::vector<float>{1.0f, 0.5f, 0.25f, 0.75f});
        CHECK(o == s);
    }
    SECTION("a point where three segments meet ends three paths") {
        CHECK(chain_segments({seg(a, b), seg(b, c), seg(b, e)}).size() == 3);
    }
}

TEST_CASE("CPU contours of a sphere: one closed loop on the contour circle", "[lines]") {
    const float R = 1.0f, D = 5.0f;
    const Mesh sphere = make_icosphere(R, 4);
    const SurfaceFields fields = compute_surface_fields(sphere);
    const glm::vec3 eye(0, 0, D);
    LineExtractionOptions o;
    const ExtractedLines lines = lines_of(sphere, fields, eye, o);
    REQUIRE(!lines[int(LineType::Contour)].empty());
    CHECK(lines[int(LineType::Suggestive)].empty());  // kr > 0 everywhere on a sphere
    const std::vector<Polyline> chained = chain_segments(lines[int(LineType::Contour)]);
    REQUIRE(chained.size() == 1);
    CHECK(chained[0].closed());
    // n.v = 0 on a sphere seen from distance D: the circle z = R^2 / D, radius
    // R sqrt(1 - R^2/D^2). The mesh's polygons (edges about 0.08 R at level
    // 4) lie within h^2 / (8R) of the sphere; allow half an edge.
    const float edge = glm::distance(sphere.positions[sphere.faces[0][0]], sphere.positions[sphere.faces[0][1]]);
    for (const glm::vec3& p : chained[0].points) {
        CHECK(std::fabs(p.z - R * R / D) < 0.5f * edge);
        CHECK(std::fabs(glm::length(glm::vec2(p.x, p.y)) - R * std::sqrt(1 - R * R / (D * D))) < 0.5f * edge);
    }
}

TEST_CASE("CPU boundaries: an open square's border is one closed loop of its four sides", "[lines]") {
    const Mesh grid = make_grid(2.0f, 4);
    const SurfaceFields fields = compute_surface_fields(grid);
    LineExtractionOptions o;
    o.contours = o.suggestive = false, o.boundaries = true;
    const ExtractedLines lines = lines_of(grid, fields, glm::vec3(0.3f, 0.2f, 3.0f), o);
    const auto& border = lines[int(LineType::Boundary)];
    CHECK(border.size() == 16);  // 4 sides x 4 edges
    const std::vector<Polyline> chained = chain_segments(border);
    REQUIRE(chained.size() == 1);
    CHECK(chained[0].closed());
}

TEST_CASE("CPU creases: a cube seen from a corner shows 9 edges, 6 of them on its outline", "[lines]") {
    const SplitMesh cube = split_at_creases(test::unit_cube(), find_creases(test::unit_cube(), 40.0f));
    const SurfaceFields fields = compute_surface_fields(cube.mesh);
    const glm::vec3 eye(3.0f, 2.5f, 4.0f);  // sees the faces +x, +y, +z
    LineExtractionOptions o;
    const ExtractedLines lines = lines_of(cube.mesh, fields, eye, o, crease_edges(cube.mesh, cube.creases, cube.crease_faces));
    CHECK(lines[int(LineType::Crease)].size() == 9);
    o.creases = false;  // contours alone: the 6 edges between a face turned towards the eye and one turned away
    const ExtractedLines outline = lines_of(cube.mesh, fields, eye, o, crease_edges(cube.mesh, cube.creases, cube.crease_faces));
    size_t on_edges = 0;
    for (const LineSegment& s : outline[int(LineType::Contour)])
        on_edges += std::fabs(glm::distance(s.a, s.b) - 1.0f) < 1e-6f;
    CHECK(on_edges == 6);
    // Chained, the outline is one closed hexagon.
    std::vector<LineSegment> hexagon;
    for (const LineSegment& s : outline[int(LineType::Contour)])
        if (std::fabs(glm::distance(s.a, s.b) - 1.0f) < 1e-6f) hexagon.push_back(s);
    const std::vector<Polyline> chained = chain_segments(hexagon);
    REQUIRE(chained.size() == 1);
    CHECK(chained[0].points.size() == 7);
}

TEST_CASE("CPU curvature and level lines lie where the mathematics puts them", "[lines]") {
    // Torus, R = 1, r = 0.6, axis z: K = 0 on the top and bottom circles
    // (|z| = r), H = 0 where cos v = -R / 2r, i.e. at distance R - R/2 from the axis.
    const float R = 1.0f, r = 0.6f;
    const Mesh torus = make_torus(R, r, 192, 96);
    const SurfaceFields fields = compute_surface_fields(torus);
    LineExtractionOptions o;
    o.contours = o.suggestive = o.creases = false;
    o.parabolic = o.mean_zero = true;
    const ExtractedLines lines = lines_of(torus, fields, glm::vec3(0, 0, 10), o);
    REQUIRE(lines[int(LineType::Parabolic)].size() > 100);
    REQUIRE(lines[int(LineType::MeanZero)].size() > 100);
    const float tol = 0.02f;  // edges are about 0.03 long; the estimate is second order
    for (const LineSegment& s : lines[int(LineType::Parabolic)]) CHECK(std::fabs(std::fabs(s.a.z) - r) < tol);
    for (const LineSegment& s : lines[int(LineType::MeanZero)])
        CHECK(std::fabs(glm::length(glm::vec2(s.a.x, s.a.y)) - 0.5f * R) < tol);
    // Both sets are two closed circles.
    CHECK(chain_segments(lines[int(LineType::Parabolic)]).size() == 2);
    CHECK(chain_segments(lines[int(LineType::MeanZero)]).size() == 2);

    // Unit sphere: isophotes are circles where n.l = (k - 1/2) / N, topographic lines where y = level.
    const Mesh sphere = make_icosphere(1.0f, 4);
    const SurfaceFields sf = compute_surface_fields(sphere);
    LineExtractionOptions lo;
    lo.contours = lo.suggestive = lo.creases = false;
    lo.isophotes = lo.topo = true;
    lo.light = glm::normalize(glm::vec3(1, 1, 1));
    lo.isophote_levels = isophote_level_set(4);
    lo.topo_levels = {-0.75f, 0.5f, 4};
    const ExtractedLines levels = lines_of(sphere, sf, glm::vec3(0, 0, 10), lo);
    CHECK(chain_segments(levels[int(LineType::Isophote)]).size() == 4);
    CHECK(chain_segments(levels[int(LineType::Topo)]).size() == 4);
    for (const LineSegment& s : levels[int(LineType::Isophote)]) {
        const float v = glm::dot(glm::normalize(s.a), lo.light);  // n = p on the unit sphere
        CHECK(std::fabs(v - s.strength_a) < 0.01f);               // the level it was cut at
        CHECK(std::fabs(std::fmod(s.strength_a * 4.0f, 1.0f) - 0.5f) < 1e-4f);  // (k - 1/2) / 4
    }
    for (const LineSegment& s : levels[int(LineType::Topo)]) CHECK(std::fabs(s.a.y - s.strength_a) < 1e-5f);
}

// view_ridge_vertices computes four vertices at once where it can and the
// rest one at a time (a thread's range need not be a multiple of four):
// both must give the bits of view_curvature, one vertex at a time, so the
// result never depends on how the vertices were split among threads.
TEST_CASE("view_ridge_vertices: four at a time gives the bits of one at a time", "[lines]") {
    const Mesh mesh = make_torus(1.0f, 0.35f, 37, 27);  // 999 vertices: ranges of any length
    const SurfaceFields fields = compute_surface_fields(mesh);
    const glm::vec3 eye(2.5f, 1.5f, 3.0f);
    const float fs = 0.3f;
    std::vector<std::vector<ViewRidgeVertex>> runs;
    for (unsigned threads : {1u, 2u, 3u, 7u}) {
        set_thread_count(threads);
        runs.push_back(view_ridge_vertices(mesh, fields, eye, fs));
    }
    set_thread_count(0);
    for (size_t r = 1; r < runs.size(); ++r)
        CHECK(std::memcmp(runs[0].data(), runs[r].data(), runs[0].size() * sizeof(ViewRidgeVertex)) == 0);
    size_t differ = 0, strong = 0;
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
        const ViewCurvature vc = view_curvature(fields.k1[i], fields.k2[i], fields.dcurv[i], fields.normals[i],
                                                fields.d1[i], fields.d2[i], eye - mesh.positions[i]);
        const ViewRidgeVertex& v = runs[0][i];
        differ += v.view_curv != std::sqrt(std::max(vc.q1, 0.0f)) * fs || v.dq1 != vc.dq1 ||
                  v.t1 != vc.t1.x * fields.d1[i] + vc.t1.y * fields.d2[i];
        strong += v.view_curv > 0.3f;
    }
    CHECK(differ == 0);
    CHECK(strong > 100);  // not all zero
    // Only the vertices asked for; the others left zero.
    std::vector<uint8_t> only(mesh.vertex_count(), 0);
    for (size_t i = 0; i < only.size(); i += 5) only[i] = 1;
    const std::vector<ViewRidgeVertex> some = view_ridge_vertices(mesh, fields, eye, fs, only);
    size_t wrong = 0;
    for (size_t i = 0; i < only.size(); ++i)
        wrong += only[i] ? std::memcmp(&some[i], &runs[0][i], sizeof(ViewRidgeVertex)) != 0
                         : some[i].view_curv != 0 || some[i].dq1 != 0 || some[i].kmax != 0;
    CHECK(wrong == 0);
}

// compute_view_quantities too: four vertices at once or one at a time, any
// thread count, the bits of the formulas written out with glm.
TEST_CASE("compute_view_quantities: four at a time gives the bits of one at a time", "[lines]") {
    const Mesh mesh = make_torus(1.0f, 0.35f, 37, 27);  // 999 vertices: ranges of any length
    const SurfaceFields fields = compute_surface_fields(mesh);
    std::vector<glm::vec3> contour_normals = fields.normals;
    for (glm::vec3& n : contour_normals) n = glm::normalize(n + glm::vec3(0.05f, -0.02f, 0.03f));
    const glm::vec3 eye(2.5f, 1.5f, 3.0f);
    const float fs = 0.3f;
    std::vector<ViewQuantities> runs;
    for (unsigned threads : {1u, 2u, 3u, 7u}) {
        set_thread_count(threads);
        runs.push_back(compute_view_quantities(mesh, fields, contour_normals, eye, fs));
    }
    set_thread_count(0);
    size_t differ = 0, suggestive = 0;
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
        const glm::vec3 v = glm::normalize(eye - mesh.positions[i]);
        const float ndotv = glm::dot(fields.normals[i], v);
        const float u = glm::dot(v, fields.d1[i]), t = glm::dot(v, fields.d2[i]);
        const float inv_sin = 1.0f / std::sqrt(std::max(u * u + t * t, 1e-12f));
        const float wu = u * inv_sin, wt = t * inv_sin;
        const glm::vec4 C = fields.dcurv[i];
        const float cwww = wu * wu * (C.x * wu + 3.0f * C.y * wt) + wt * wt * (3.0f * C.z * wu + C.w * wt);
        const float tau = (fields.k2[i] - fields.k1[i]) * wu * wt;
        const float kr = fields.k1[i] * u * u + fields.k2[i] * t * t;
        const float sc = (cwww - 2.0f * tau * tau * (ndotv * inv_sin)) * (fs * fs);
        for (const ViewQuantities& q : runs)
            differ += q.ndotv[i] != ndotv || q.contour_ndotv[i] != glm::dot(contour_normals[i], v) || q.kr[i] != kr ||
                      q.sc_strength[i] != sc;
        suggestive += sc > 0.05f;
    }
    CHECK(differ == 0);
    CHECK(suggestive > 50);  // not all zero
    std::vector<uint8_t> only(mesh.vertex_count(), 0);
    for (size_t i = 0; i < only.size(); i += 5) only[i] = 1;
    const ViewQuantities some = compute_view_quantities(mesh, fields, contour_normals, eye, fs, only);
    size_t wrong = 0;
    for (size_t i = 0; i < only.size(); ++i)
        wrong += only[i] ? some.kr[i] != runs[0].kr[i] || some.sc_strength[i] != runs[0].sc_strength[i]
                         : some.kr[i] != 0 || some.ndotv[i] != 0;
    CHECK(wrong == 0);
}

// LineExtractionOptions::cull_back_faces (rtsc's back-face culling): the
// triangles turned away from the eye at all three corners keep their
// contours and nothing else; the other triangles keep all their lines.
TEST_CASE("culling back faces drops exactly the lines of triangles turned away", "[lines]") {
    const Mesh sphere = make_icosphere(1.0f, 4);
    const SurfaceFields fields = compute_surface_fields(sphere);
    const glm::vec3 eye(0.3f, 0.4f, 4.0f);
    LineExtractionOptions o;
    o.suggestive = o.creases = false;
    o.isophotes = o.topo = o.mean_zero = true;  // H = -1 everywhere: no mean-zero line; the levels cover the sphere
    o.light = glm::normalize(glm::vec3(1, 0.2f, -0.5f));
    o.isophote_levels = isophote_level_set(6);
    o.topo_levels = {-0.9f, 0.1f, 19};
    const ExtractedLines all = lines_of(sphere, fields, eye, o);
    o.cull_back_faces = true;
    const ExtractedLines culled = lines_of(sphere, fields, eye, o);
    CHECK(culled[int(LineType::Contour)].size() == all[int(LineType::Contour)].size());
    // A segment's triangle turned towards the eye has a corner with n.(eye - p) = p.eye - 1 > 0 (the
    // unit sphere: n = p); across the triangle p.eye changes by at most |eye| times its longest edge.
    float longest = 0;
    for (const Face& t : sphere.faces)
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, glm::distance(sphere.positions[t[k]], sphere.positions[t[(k + 1) % 3]]));
    const float reach = glm::length(eye) * longest;
    for (const LineType type : {LineType::Isophote, LineType::Topo}) {
        const auto& kept = culled[int(type)];
        const auto& every = all[int(type)];
        size_t front = 0;
        for (const LineSegment& s : every) front += glm::dot(s.a, eye - s.a) > 0.05f && glm::dot(s.b, eye - s.b) > 0.05f;
        INFO(line_type_name(type) << ": " << every.size() << " segments, " << kept.size() << " kept, " << front
                                  << " clearly in front");
        CHECK(kept.size() >= front);
        CHECK(kept.size() < every.size() * 3 / 4);  // about half the sphere is turned away
        size_t beyond = 0;
        for (const LineSegment& s : kept) beyond += std::max(glm::dot(s.a, eye - s.a), glm::dot(s.b, eye - s.b)) < -reach;
        CHECK(beyond == 0);
    }
}
