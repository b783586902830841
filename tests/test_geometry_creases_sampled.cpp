// The shortcuts that find creases on big meshes without looking at every
// edge (geometry/mesh/crease_vote.h, crease_candidates.h, face_survey.h)
// give what the whole count gives: the sampled `auto` vote agrees with it
// far from half (and leaves meshes at half to it), and the creases found
// around the candidates are the whole pass's, at angles just above and
// below the bends of a mesh.
#include "test_support.h"

#include "geometry/io/mesh_io.h"
#include "geometry/mesh/crease_candidates.h"
#include "geometry/mesh/crease_vote.h"
#include "geometry/mesh/creases.h"
#include "geometry/mesh/edge_bends.h"
#include "geometry/mesh/edge_table.h"
#include "geometry/mesh/face_survey.h"
#include "geometry/mesh/orientation.h"
#include "geometry/mesh/primitives.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace kappa;

namespace {

// An n x n grid of unit squares, two triangles each, at height z(i, j),
// moved along x by `offset` (grids side by side make one mesh).
template <typename Height>
void add_grid(Mesh& m, int n, float offset, Height&& z) {
    const uint32_t first = uint32_t(m.positions.size());
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) m.positions.push_back({offset + float(i), float(j), z(i, j)});
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const uint32_t a = first + uint32_t(j * n + i), b = a + 1, c = a + uint32_t(n), d = c + 1;
            m.faces.push_back({a, b, d});
            m.faces.push_back({a, d, c});
        }
}

// Flat: every interior edge turns by 0 degrees (not between 0.5 and 40).
void add_flat(Mesh& m, int n, float offset) {
    add_grid(m, n, offset, [](int, int) { return 0.0f; });
}

// Random heights: nearly every interior edge bends by a few degrees (between).
void add_bumpy(Mesh& m, int n, float offset) {
    std::mt19937 rng{uint32_t(n)};
    std::uniform_real_distribution<float> height(-0.05f, 0.05f);
    std::vector<float> z(size_t(n) * size_t(n));
    for (float& h : z) h = height(rng);
    add_grid(m, n, offset, [&](int i, int j) { return z[size_t(j) * size_t(n) + size_t(i)]; });
}

// Flat pieces with `count` interior edges in all: a grid of g^2 vertices ((g - 1)(3g - 5) of them),
// then single squares (one each).
void add_flat_edges(Mesh& m, size_t count, float offset) {
    int g = 2;
    while (size_t(g) * size_t(3 * g - 2) <= count) ++g;  // the next grid's g (3g - 2) still fits
    if (g > 2) add_flat(m, g, offset);
    const size_t in_grid = g > 2 ? size_t(g - 1) * size_t(3 * g - 5) : 0;
    for (size_t k = 0; k < count - in_grid; ++k) add_flat(m, 2, offset + float(g + 1) + 2.0f * float(k));
}

CreaseVote full_vote(const Mesh& m) {
    return auto_creases_on(measure_edge_bends(m, build_vertex_faces(m), 0)) ? CreaseVote::On : CreaseVote::Off;
}

}  // namespace

TEST_CASE("Creases: the sampled auto vote agrees with the whole count, and leaves half to it", "[creases]") {
    // Big enough to be sampled (8 x 32768 vertices or more).
    const int n = 363;
    Mesh flat, bumpy, mostly_flat, mostly_bumpy;
    add_flat(flat, 2 * n, 0);
    add_bumpy(bumpy, 2 * n, 0);
    add_flat(mostly_flat, n + 60, 0), add_bumpy(mostly_flat, n - 60, float(n + 61));
    add_flat(mostly_bumpy, n - 60, 0), add_bumpy(mostly_bumpy, n + 60, float(n - 59));
    // Right at the boundary: bumpy, then as many flat edges as make the bent ones exactly half
    // (creases on), or one fewer (just over half: off), or one more (just under: on).
    Mesh even, just_over, just_under;
    const EdgeBends b = [&] {
        Mesh m;
        add_bumpy(m, 2 * n, 0);
        return measure_edge_bends(m, build_vertex_faces(m), 0);
    }();
    REQUIRE(2 * b.between > b.interior);
    const size_t flat_edges = 2 * b.between - b.interior;
    for (auto [mesh, count] : {std::pair<Mesh*, size_t>{&even, flat_edges}, {&just_over, flat_edges - 1},
                               {&just_under, flat_edges + 1}}) {
        add_bumpy(*mesh, 2 * n, 0);
        add_flat_edges(*mesh, count, float(2 * n + 1));
    }
    const EdgeBends e = measure_edge_bends(even, build_vertex_faces(even), 0);
    REQUIRE(2 * e.between == e.interior);
    struct Case {
        const char* name;
        const Mesh* mesh;
        CreaseVote expected;  // of the whole count
        bool sampled;         // whether the sample decides
    };
    const Case cases[] = {{"flat", &flat, CreaseVote::On, true},
                          {"bumpy", &bumpy, CreaseVote::Off, true},
                          {"mostly flat (about 0.4)", &mostly_flat, CreaseVote::On, true},
                          {"mostly bumpy (about 0.6)", &mostly_bumpy, CreaseVote::Off, true},
                          {"exactly half", &even, CreaseVote::On, false},
                          {"just over half", &just_over, CreaseVote::Off, false},
                          {"just under half", &just_under, CreaseVote::On, false}};
    for (const Case& c : cases) {
        INFO(c.name);
        REQUIRE(c.mesh->vertex_count() >= 8 * kVoteSamples);
        const CreaseVote whole = full_vote(*c.mesh);
        CHECK(whole == c.expected);
        const VertexFaces vf = build_vertex_faces(*c.mesh);
        size_t looked_at = 0;
        const CreaseVote sampled = sampled_crease_vote(*c.mesh, vf, &looked_at);
        CHECK(sampled == (c.sampled ? whole : CreaseVote::Unclear));
        // Far from half, the first stage's vertices decide; near it, the whole sample is looked at.
        CHECK(looked_at == (c.sampled ? kVoteSamples / kFirstStage : kVoteSamples));
        const float angle = whole == CreaseVote::On ? kAutoCreaseAngle : 0.0f;
        CHECK(auto_crease_angle(*c.mesh) == angle);
        CHECK(resolve_creases(*c.mesh, vf, -1).angle == angle);
    }
    // A real smooth mesh big enough to be sampled: bunny-1M (66% between).
    const Mesh bunny = load_mesh(test::shared_mesh("bunny-1M.ply"));
    const VertexFaces vf = build_vertex_faces(bunny);
    CHECK(full_vote(bunny) == CreaseVote::Off);
    size_t looked_at = 0;
    CHECK(sampled_crease_vote(bunny, vf, &looked_at) == CreaseVote::Off);
    CHECK(looked_at == kVoteSamples / kFirstStage);
    // Small meshes are always counted whole.
    const Mesh small = make_icosphere(1, 4);
    CHECK(sampled_crease_vote(small, build_vertex_faces(small)) == CreaseVote::Unclear);
}

namespace {

// A square grid folded along its columns: the strip between
// columns i and i + 1 rises at angle tilt[i] (degrees), so the edges along
// column i turn by |tilt[i] - tilt[i - 1]|.
Mesh folded(const std::vector<double>& tilt) {
    Mesh m;
    const int n = int(tilt.size()) + 1;
    std::vector<double> z(size_t(n), 0.0);
    for (int i = 1; i < n; ++i) z[size_t(i)] = z[size_t(i - 1)] + std::tan(tilt[size_t(i - 1)] * M_PI / 180.0);
    add_grid(m, n, 0, [&](int i, int) { return float(z[size_t(i)]); });
    return m;
}

// Each crease's vertices are candidates, and the creases around the
// candidates are the whole pass's, in the same order.
void check_candidates(const Mesh& m, float angle) {
    INFO("angle " << angle);
    const VertexFaces vf = build_vertex_faces(m);
    const EdgeBends whole = measure_edge_bends(m, vf, angle);
    const std::vector<uint32_t> candidates = crease_candidates(m, vf, angle);
    for (const glm::uvec2& c : whole.creases) {
        CHECK(std::binary_search(candidates.begin(), candidates.end(), c.x));
        CHECK(std::binary_search(candidates.begin(), candidates.end(), c.y));
    }
    const EdgeBends around = measure_edge_bends_at(m, vf, angle, candidates);
    CHECK(around.creases == whole.creases);
    CHECK(around.crease_faces == whole.crease_faces);
    CHECK(creases_around(m, vf, angle, candidates) == whole.creases);
    CHECK(find_creases(m, angle) == whole.creases);
}

}  // namespace

TEST_CASE("Creases: those found around the candidates are the whole pass's", "[creases]") {
    // Folds just above and just below 40 and 10 degrees, and far from them.
    std::vector<double> tilt{-40};
    int folds_over_40 = 0;
    for (const double fold : {40.01, 39.99, 40.001, 39.999, 40.0001, 39.9999, 10.001, 9.999, 80.0, 1.0, 0.3}) {
        tilt.push_back(tilt.back() + (tilt.back() < 0 ? fold : -fold));  // up and down, within +-80
        tilt.push_back(tilt.back());  // a flat strip between folds
        folds_over_40 += fold > 40;
    }
    const Mesh fold = folded(tilt);
    for (const float angle : {40.0f, 10.0f, 5.0f, 60.0f, 0.5f, 0.2f, 179.0f}) check_candidates(fold, angle);
    CHECK(find_creases(fold, 40).size() == tilt.size() * size_t(folds_over_40));  // a column of edges a fold

    Mesh fandisk = load_mesh(test::shared_mesh("fandisk.obj"));
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> jitter(-0.004f, 0.004f);
    Mesh jittered = fandisk;
    for (glm::vec3& p : jittered.positions) p += glm::vec3(jitter(rng), jitter(rng), jitter(rng));
    for (const Mesh* m : {&fandisk, &jittered})
        for (const float angle : {kAutoCreaseAngle, 10.0f, 20.0f, 60.0f, 89.0f, 150.0f}) check_candidates(*m, angle);
    // Turned inside out, the candidates of the mesh as it was still hold (prepare_for_drawing turns it after the pass).
    Mesh turned = jittered;
    flip_faces(turned);
    const VertexFaces jittered_rows = build_vertex_faces(jittered);
    const std::vector<uint32_t> before = crease_candidates(jittered, jittered_rows, 20);
    CHECK(creases_around(turned, build_vertex_faces(turned), 20, before) ==
          measure_edge_bends(turned, build_vertex_faces(turned), 20).creases);
    // Whatever the thread count: the same candidates, so the same creases.
    set_thread_count(1);
    const std::vector<uint32_t> one = crease_candidates(jittered, jittered_rows, 20);
    set_thread_count(0);
    CHECK(crease_candidates(jittered, jittered_rows, 20) == one);
}

TEST_CASE("Crease candidates: a direction lies within kPackAngleDeg of its packing, packed alike in lanes",
          "[creases]") {
    // The candidates compare packed directions: sound only if every direction lies within kPackAngleDeg
    // of its packing.
    auto unpacked = [](uint32_t packed) {
        auto component = [&](int k) { return float(int32_t(packed << (27 - 5 * k)) >> 27); };
        return glm::vec3(component(0), component(1), component(2));
    };
    std::mt19937 rng(11);
    std::normal_distribution<float> gauss;
    std::uniform_real_distribution<float> scale(-30.0f, 30.0f);
    double widest = 0;
    for (int i = 0; i < 200000; ++i) {
        glm::vec3 n[4];
        for (glm::vec3& d : n) {
            d = glm::vec3(gauss(rng), gauss(rng), gauss(rng));
            // Near the packing's rounding edges too: components at half steps of the grid.
            if (i % 4 == 1) d = glm::vec3(15.0f, std::round(d.y * 7.0f) + 0.5f, std::round(d.z * 7.0f) + 0.5f);
            if (i % 4 == 2) d.z = 0;
            d *= std::exp2(scale(rng));  // any length
        }
        const lanes::Lanes x{n[0].x, n[1].x, n[2].x, n[3].x}, y{n[0].y, n[1].y, n[2].y, n[3].y},
            z{n[0].z, n[1].z, n[2].z, n[3].z};
        const lanes::Ints4 four = CreaseCandidateTest::pack_direction(x, y, z);
        for (int j = 0; j < 4; ++j) {
            const uint32_t packed = CreaseCandidateTest::pack_direction(n[j].x, n[j].y, n[j].z);
            REQUIRE(uint32_t(four[j]) == packed);
            const glm::vec3 r = unpacked(packed);
            const double cosine = glm::dot(glm::dvec3(n[j]), glm::dvec3(r)) /
                                  (glm::length(glm::dvec3(n[j])) * glm::length(glm::dvec3(r)));
            widest = std::max(widest, std::acos(std::min(1.0, cosine)) * 180.0 / M_PI);
        }
    }
    CHECK(widest <= CreaseCandidateTest::kPackAngleDeg);
    CHECK(widest > 2.0);  // the bound is near what the packing gives
}

TEST_CASE("Crease candidates: a face the test keeps lies within the half angle of the reference",
          "[creases]") {
    // keeps(pack of n, r) must leave n within half the angle (less the margin for edge_bends' roundings)
    // of r, whatever n and r: then no two faces kept by one r turn by the angle.
    std::mt19937 rng(17);
    std::normal_distribution<float> gauss;
    for (const float angle : {kAutoCreaseAngle, 12.0f, 20.0f, 90.0f, 179.0f}) {
        INFO("angle " << angle);
        const CreaseCandidateTest test(angle);
        REQUIRE(!test.everywhere());
        const double half = 0.5 * std::acos(double(std::cos(angle * float(M_PI) / 180.0f)) + 4e-6) * 180.0 / M_PI;
        double widest_kept = 0;
        int kept = 0;
        for (int i = 0; i < 200000; ++i) {
            const glm::vec3 n(gauss(rng), gauss(rng), gauss(rng));
            const glm::vec3 m = n + glm::vec3(gauss(rng), gauss(rng), gauss(rng)) * (0.01f * float(i % 50));
            const int32_t r = CreaseCandidateTest::pack_direction(m.x, m.y, m.z);
            const int32_t p = CreaseCandidateTest::pack_direction(n.x, n.y, n.z);
            if (!test.keeps(p, r)) continue;
            auto unpacked = [](uint32_t packed) {
                auto component = [&](int k) { return double(int32_t(packed << (27 - 5 * k)) >> 27); };
                return glm::dvec3(component(0), component(1), component(2));
            };
            const glm::dvec3 rd = unpacked(uint32_t(r));
            const double cosine = glm::dot(glm::dvec3(n), rd) / (glm::length(glm::dvec3(n)) * glm::length(rd));
            widest_kept = std::max(widest_kept, std::acos(std::min(1.0, cosine)) * 180.0 / M_PI);
            ++kept;
        }
        CHECK(widest_kept <= half);
        CHECK(widest_kept > half - 2 * CreaseCandidateTest::kPackAngleDeg);  // not far inside it either
        CHECK(kept > 1000);
    }
    CHECK(CreaseCandidateTest(5.0f).everywhere());  // no room under twice kPackAngleDeg
    CHECK(!CreaseCandidateTest(6.0f).everywhere());
}

namespace {

// crease_candidates.h's rule, vertex by vertex: r is the pack of the first face in the vertex's row that
// is not left out, and the vertex is a candidate if a face in its row has no normal or a pack the test
// does not keep with r.
std::vector<uint32_t> candidates_by_the_rule(const Mesh& mesh, const VertexFaces& vf, float angle) {
    const CreaseCandidateTest test(angle);
    const size_t nv = mesh.vertex_count();
    std::vector<uint32_t> expected;
    for (uint32_t v = 0; v < nv; ++v) {
        int32_t r = -1;
        bool candidate = false;
        for (uint32_t i = vf.begin(v); i < vf.end(v); ++i) {
            const Face& f = mesh.faces[vf.corners[i] / 3];
            if (!is_valid_face(f, nv)) continue;
            const glm::vec3 c = face_cross(mesh, f);
            if (!(glm::dot(c, c) > 0)) {
                candidate = true;
                break;
            }
            const int32_t p = CreaseCandidateTest::pack_direction(c.x, c.y, c.z);
            if (r < 0) r = p;
            if (!test.keeps(p, r)) candidate = true;
        }
        if (candidate) expected.push_back(v);
    }
    return expected;
}

// Faces that test the passes' odd cases: a repeated corner (no edges), a degenerate face (no normal)
// first in its corners' rows (before every other face) and last.
void add_odd_faces(Mesh& mesh) {
    mesh.faces.insert(mesh.faces.begin(), Face{7, 8, 9});
    mesh.positions[9] = mesh.positions[8];
    mesh.faces.push_back({0, 0, 1});
    mesh.faces.push_back({2, 3, 4});
    mesh.positions[4] = mesh.positions[3];
}

}  // namespace

TEST_CASE("The pass over the faces: its candidates are those of the rule taken vertex by vertex", "[creases]") {
    // survey_faces takes four faces at a time in three passes, and collects the candidates from what the
    // passes noted where they are few (the sphere), else from the vertices' marks (jittered fandisk).
    Mesh fandisk = load_mesh(test::shared_mesh("fandisk.obj"));
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> jitter(-0.004f, 0.004f);
    for (glm::vec3& p : fandisk.positions) p += glm::vec3(jitter(rng), jitter(rng), jitter(rng));
    Mesh sphere = make_icosphere(1.0f, 6);  // 41k vertices, faces about a degree apart
    for (Mesh* mesh : {&fandisk, &sphere}) {
        add_odd_faces(*mesh);
        const size_t nv = mesh->vertex_count();
        const VertexFaces vf = build_vertex_faces(*mesh);
        // A face with a missing corner (left out), after the rows: they are made of valid corners only.
        mesh->faces.push_back({5, 6, uint32_t(nv)});
        for (const float angle : {kAutoCreaseAngle, 12.0f, 20.0f}) {
            INFO((mesh == &sphere ? "sphere" : "fandisk") << ", angle " << angle);
            const std::vector<uint32_t> expected = candidates_by_the_rule(*mesh, vf, angle);
            const FaceSurvey survey = survey_faces(*mesh, vf, angle);
            CHECK(survey.crease_candidates == expected);
            for (const uint32_t v : {3u, 8u})  // the degenerate faces' corners
                CHECK(std::binary_search(expected.begin(), expected.end(), v));
            if (angle == kAutoCreaseAngle) CHECK(expected.size() < nv / 3);  // a shortcut, even on this noise
            if (mesh == &sphere && angle != 12.0f) CHECK(expected.size() < nv / 64);  // few: the noted path
        }
        CHECK(survey_faces(*mesh, vf, 5.0f).crease_candidates.size() == nv);  // no room: every vertex
    }
}

TEST_CASE("The pass over the faces: volumes as the inside-out test sums them, whatever the thread count",
          "[creases][orientation]") {
    Mesh bunny = load_mesh(test::shared_mesh("bunny.ply"));
    set_thread_count(1);
    const VertexFaces rows = build_vertex_faces(bunny);
    const FaceSurvey one = survey_faces(bunny, rows, kAutoCreaseAngle);
    set_thread_count(0);
    const FaceSurvey many = survey_faces(bunny, rows, kAutoCreaseAngle);
    CHECK(one.crease_candidates == many.crease_candidates);
    CHECK(one.volumes.signed_sum == many.volumes.signed_sum);
    CHECK(one.volumes.unsigned_sum == many.volumes.unsigned_sum);
    // The serial sum of the same terms in double, from the same apex (the centroid in float). The pass
    // takes each term's dot product in float: the subtraction from the apex, three products and two sums
    // round it by at most about 4 units in the last place of sum_k |a_k c_k| (margin: 8); the double sums
    // in a different order by far less.
    const glm::dvec3 apex(glm::vec3(vertex_centroid(bunny)));
    double signed_sum = 0, unsigned_sum = 0, rounding = 0;
    for (const Face& f : bunny.faces) {
        const double v = tetrahedron_volume6(bunny, f, apex);
        signed_sum += v, unsigned_sum += std::fabs(v);
        const glm::dvec3 a = glm::dvec3(bunny.positions[f[0]]) - apex;
        const glm::dvec3 c(face_cross(bunny, f));
        rounding += 8 * std::ldexp(std::fabs(a.x * c.x) + std::fabs(a.y * c.y) + std::fabs(a.z * c.z), -24);
    }
    const double bound = rounding + 1e-12 * unsigned_sum;
    CHECK(rounding < 1e-4 * unsigned_sum);  // a bound that still means something
    CHECK(std::fabs(many.volumes.signed_sum - signed_sum) <= bound);
    CHECK(std::fabs(many.volumes.unsigned_sum - unsigned_sum) <= bound);
    CHECK(!is_inside_out(many.volumes));
    flip_faces(bunny);
    CHECK(is_inside_out(survey_faces(bunny, rows, 0).volumes));
}
