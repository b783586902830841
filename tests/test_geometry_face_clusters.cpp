// Face clusters (partition, connectivity, compactness, determinism) and their
// view-culling bounds: classify_facing() is checked against brute force over
// every vertex and face normal of every cluster, for many eye points.
#include <catch2/catch.hpp>

#include "test_support.h"

#include "geometry/culling/cluster_bounds.h"
#include "geometry/culling/face_clusters.h"
#include "geometry/curvature/face_geometry.h"
#include "geometry/io/mesh_io.h"
#include "geometry/curvature/vertex_basics.h"
#include "geometry/mesh/primitives.h"
#include "geometry/mesh/vertex_faces.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_map>

using namespace kappa;

namespace {

std::vector<glm::vec3> normals_of(const Mesh& m) {
    return compute_vertex_basics(build_vertex_faces(m), compute_face_geometry(m)).normals;
}

// Appends b to a (indices shifted).
Mesh merged(Mesh a, const Mesh& b, glm::vec3 offset) {
    const uint32_t base = uint32_t(a.positions.size());
    for (auto p : b.positions) a.positions.push_back(p + offset);
    for (auto f : b.faces) a.faces.push_back(f + glm::uvec3(base));
    return a;
}

// Every face exactly once, every cluster 1..max_faces faces.
void check_partition(const Mesh& m, const FaceClusters& cl, uint32_t max_faces) {
    REQUIRE(cl.face_order.size() == m.face_count());
    REQUIRE(cl.cluster_start.size() == cl.size() + 1);
    REQUIRE(cl.cluster_start.front() == 0);
    REQUIRE(cl.cluster_start.back() == m.face_count());
    std::vector<uint32_t> sorted = cl.face_order;
    std::sort(sorted.begin(), sorted.end());
    size_t not_permutation = 0;
    for (size_t f = 0; f < sorted.size(); ++f) not_permutation += sorted[f] != f;
    CHECK(not_permutation == 0);
    size_t bad_sizes = 0;
    for (size_t c = 0; c < cl.size(); ++c) {
        const uint32_t n = cl.cluster_start[c + 1] - cl.cluster_start[c];
        bad_sizes += n < 1 || n > max_faces;
    }
    CHECK(bad_sizes == 0);
    // vertex_order: a permutation of the vertices, in order of first use by
    // the faces in face_order, the unused ones last in increasing order.
    REQUIRE(cl.vertex_order.size() == m.vertex_count());
    std::vector<uint32_t> expected;
    std::vector<uint8_t> seen(m.vertex_count(), 0);
    for (uint32_t f : cl.face_order)
        for (int j = 0; j < 3; ++j)
            if (!seen[m.faces[f][j]]) seen[m.faces[f][j]] = 1, expected.push_back(m.faces[f][j]);
    for (uint32_t v = 0; v < m.vertex_count(); ++v)
        if (!seen[v]) expected.push_back(v);
    CHECK(cl.vertex_order == expected);
    // vertex_slot: its inverse.
    REQUIRE(cl.vertex_slot.size() == m.vertex_count());
    size_t not_inverse = 0;
    for (uint32_t i = 0; i < m.vertex_count(); ++i) not_inverse += cl.vertex_slot[cl.vertex_order[i]] != i;
    CHECK(not_inverse == 0);
}

// Number of clusters whose faces are not connected through shared vertices.
size_t disconnected_clusters(const Mesh& m, const FaceClusters& cl) {
    size_t bad = 0;
    for (size_t c = 0; c < cl.size(); ++c) {
        const uint32_t begin = cl.cluster_start[c], end = cl.cluster_start[c + 1];
        std::unordered_map<uint32_t, std::vector<uint32_t>> faces_at;  // vertex -> local faces
        for (uint32_t i = begin; i < end; ++i)
            for (int j = 0; j < 3; ++j) faces_at[m.faces[cl.face_order[i]][j]].push_back(i - begin);
        std::vector<uint8_t> reached(end - begin, 0);
        std::vector<uint32_t> stack{0};
        reached[0] = 1;
        size_t count = 1;
        while (!stack.empty()) {
            const uint32_t i = stack.back();
            stack.pop_back();
            for (int j = 0; j < 3; ++j)
                for (uint32_t k : faces_at[m.faces[cl.face_order[begin + i]][j]])
                    if (!reached[k]) {
                        reached[k] = 1;
                        ++count;
                        stack.push_back(k);
                    }
        }
        bad += count != end - begin;
    }
    return bad;
}

// Face normal exactly as the header defines it; false where it is not finite.
bool face_normal(const Mesh& m, const Face& f, glm::vec3& n) {
    const glm::vec3 p0 = m.positions[f[0]];
    n = glm::normalize(glm::cross(m.positions[f[1]] - p0, m.positions[f[2]] - p0));
    return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z);
}

// What a cluster holds, for brute force: (point, normal) pairs, the vertex
// normals at the vertices and each face normal at its three vertices.
struct Samples {
    std::vector<std::vector<std::pair<glm::dvec3, glm::dvec3>>> of_cluster;
};

Samples samples_of(const Mesh& m, const std::vector<glm::vec3>& normals, const FaceClusters& cl) {
    Samples s;
    s.of_cluster.resize(cl.size());
    for (size_t c = 0; c < cl.size(); ++c)
        for (uint32_t i = cl.cluster_start[c]; i < cl.cluster_start[c + 1]; ++i) {
            const Face& f = m.faces[cl.face_order[i]];
            glm::vec3 fn;
            const bool has_normal = face_normal(m, f, fn);
            for (int j = 0; j < 3; ++j) {
                s.of_cluster[c].emplace_back(m.positions[f[j]], normals[f[j]]);
                if (has_normal) s.of_cluster[c].emplace_back(m.positions[f[j]], fn);
            }
        }
    return s;
}

struct FacingCounts {
    size_t front = 0, back = 0, mixed = 0, wrong = 0;
};

// Classifies every cluster for `eye` and checks Front / Back against brute
// force (in double precision: the exact sign of dot(n, eye - p)).
void check_eye(const std::vector<ClusterBounds>& bounds, const Samples& s, glm::vec3 eye, FacingCounts& counts) {
    for (size_t c = 0; c < bounds.size(); ++c) {
        const Facing facing = classify_facing(bounds[c], eye);
        if (facing == Facing::Mixed) {
            ++counts.mixed;
            continue;
        }
        (facing == Facing::Front ? counts.front : counts.back)++;
        const double sign = facing == Facing::Front ? 1.0 : -1.0;
        for (const auto& [p, n] : s.of_cluster[c])
            if (!(sign * glm::dot(n, glm::dvec3(eye) - p) > 0)) {
                ++counts.wrong;
                break;
            }
    }
}

// Eye points of every kind around a mesh: inside and around its bounding
// box, near the surface on both sides, exactly at vertices, and far away.
std::vector<glm::vec3> eyes_around(const Mesh& m, const std::vector<glm::vec3>& normals, uint32_t seed) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (auto p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 center = 0.5f * (lo + hi);
    const float radius = 0.5f * glm::length(hi - lo);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_int_distribution<size_t> vertex(0, m.vertex_count() - 1);
    auto direction = [&] {
        glm::vec3 d;
        do d = glm::vec3(unit(rng), unit(rng), unit(rng));
        while (glm::dot(d, d) > 1 || glm::dot(d, d) < 1e-4f);
        return glm::normalize(d);
    };
    std::vector<glm::vec3> eyes;
    for (int i = 0; i < 40; ++i) eyes.push_back(center + 1.5f * radius * glm::vec3(unit(rng), unit(rng), unit(rng)));
    for (float t : {1e-4f, 1e-2f, 0.1f})
        for (int i = 0; i < 12; ++i) {
            const size_t v = vertex(rng);
            const float side = i % 2 ? 1.0f : -1.0f;
            eyes.push_back(m.positions[v] + side * t * radius * (normals[v] + 0.3f * direction()));
        }
    for (int i = 0; i < 8; ++i) eyes.push_back(m.positions[vertex(rng)]);
    for (float d : {1.05f, 2.0f, 3.0f, 10.0f, 1e3f, 1e5f})
        for (int i = 0; i < 8; ++i) eyes.push_back(center + d * radius * direction());
    return eyes;
}

// Runs the brute-force check for all eyes on one mesh; returns the counts.
FacingCounts check_mesh(const Mesh& m, const std::vector<glm::vec3>& normals, uint32_t max_faces, uint32_t seed) {
    const FaceClusters cl = cluster_faces(m, max_faces);
    const std::vector<ClusterBounds> bounds = compute_cluster_bounds(m, normals, cl);
    REQUIRE(bounds.size() == cl.size());
    const Samples s = samples_of(m, normals, cl);
    FacingCounts counts;
    for (glm::vec3 eye : eyes_around(m, normals, seed)) check_eye(bounds, s, eye, counts);
    return counts;
}

// Fractions of clusters classified Front / Back for one eye.
std::pair<double, double> front_back_fractions(const std::vector<ClusterBounds>& bounds, glm::vec3 eye) {
    size_t front = 0, back = 0;
    for (const ClusterBounds& b : bounds) {
        const Facing f = classify_facing(b, eye);
        front += f == Facing::Front;
        back += f == Facing::Back;
    }
    return {double(front) / double(bounds.size()), double(back) / double(bounds.size())};
}

}  // namespace

TEST_CASE("face clusters partition the faces into connected clusters of 1..max_faces", "[geometry][clusters]") {
    const Mesh meshes[] = {make_icosphere(1.0f, 5), make_torus(1.0f, 0.3f, 90, 30),
                           make_jittered_sphere(1.0f, 4, 0.8f, 7), make_grid(2.0f, 40),
                           make_uv_sphere(1.0f, 30, 40)};
    for (const Mesh& m : meshes)
        for (uint32_t max_faces : {1u, 7u, 64u, 256u, 100000u}) {
            INFO("faces " << m.face_count() << ", max_faces " << max_faces);
            const FaceClusters cl = cluster_faces(m, max_faces);
            check_partition(m, cl, max_faces);
            CHECK(disconnected_clusters(m, cl) == 0);
            // A connected mesh: only the leftovers the greedy growth walls in are
            // small, so the clusters are not many more than F / max_faces.
            CHECK(cl.size() <= 2 * (m.face_count() + max_faces - 1) / max_faces);
            // Deterministic.
            const FaceClusters again = cluster_faces(m, max_faces);
            CHECK(again.face_order == cl.face_order);
            CHECK(again.cluster_start == cl.cluster_start);
        }
}

TEST_CASE("face clusters: empty mesh, max_faces 0, many components", "[geometry][clusters]") {
    const FaceClusters empty = cluster_faces(Mesh{});
    CHECK(empty.size() == 0);
    CHECK(empty.face_order.empty());
    CHECK(empty.vertex_order.empty());
    CHECK(empty.vertex_slot.empty());
    // Vertices no face uses come last, in their own order.
    Mesh loose = make_icosphere(1.0f, 1);
    loose.positions.insert(loose.positions.begin(), glm::vec3(5, 0, 0));
    for (Face& f : loose.faces) f += glm::uvec3(1);
    loose.positions.push_back(glm::vec3(6, 0, 0));
    const FaceClusters with_loose = cluster_faces(loose, 16);
    check_partition(loose, with_loose, 16);
    REQUIRE(with_loose.vertex_order.size() == loose.vertex_count());
    CHECK(with_loose.vertex_order[loose.vertex_count() - 2] == 0);
    CHECK(with_loose.vertex_order.back() == loose.vertex_count() - 1);
    CHECK(compute_cluster_bounds(Mesh{}, {}, empty).empty());

    const Mesh tet = make_icosphere(1.0f, 0);
    const FaceClusters ones = cluster_faces(tet, 0);  // treated as 1
    check_partition(tet, ones, 1);
    CHECK(ones.size() == tet.face_count());

    // Every face around one vertex (a fan of 300k faces): linear time, not once per cluster.
    Mesh fan;
    const uint32_t n = 300000;
    fan.positions.push_back({0, 0, 0});
    for (uint32_t i = 0; i <= n; ++i) {
        const float a = 6.2831853f * float(i) / float(n);
        fan.positions.push_back({std::cos(a), std::sin(a), 0.1f * std::sin(7 * a)});
    }
    for (uint32_t i = 0; i < n; ++i) fan.faces.push_back({0, i + 1, i + 2});
    const FaceClusters fan_clusters = cluster_faces(fan, 256);
    check_partition(fan, fan_clusters, 256);
    CHECK(fan_clusters.size() == (n + 255) / 256);
    CHECK(cluster_faces(fan, 4000000000u).size() == 1);

    // 30 small spheres: no cluster spans two of them (clusters are connected).
    Mesh many;
    for (int i = 0; i < 30; ++i) many = merged(many, make_icosphere(0.4f, 1 + i % 3), glm::vec3(float(i), 0, 0));
    const FaceClusters cl = cluster_faces(many, 50);
    check_partition(many, cl, 50);
    CHECK(disconnected_clusters(many, cl) == 0);
}

TEST_CASE("face clusters on a fine sphere are compact, with narrow normal cones", "[geometry][clusters]") {
    const Mesh m = make_icosphere(1.0f, 6);  // 81920 faces
    const uint32_t max_faces = 256;
    const FaceClusters cl = cluster_faces(m, max_faces);
    check_partition(m, cl, max_faces);
    const std::vector<ClusterBounds> bounds = compute_cluster_bounds(m, normals_of(m), cl);

    // A geodesic disk of max_faces faces has radius ~ sqrt(max_faces * face area / pi) = 0.11.
    const double face_area = 4 * M_PI / double(m.face_count());
    const double disk = std::sqrt(max_faces * face_area / M_PI);
    std::vector<double> ratios, angles;
    size_t inconsistent = 0;
    for (const ClusterBounds& b : bounds) {
        REQUIRE(b.cos_angle > 0);  // a patch of a convex surface: never "all directions"
        const double alpha = std::atan2(double(b.sin_angle), double(b.cos_angle));
        ratios.push_back(b.radius / disk);
        angles.push_back(alpha);
        // On the unit sphere the normal at p is p: every normal lies within
        // asin(r / |center|) of the centre's direction, so within twice that of the axis.
        const double theta = std::asin(std::min(1.0, double(b.radius) / double(glm::length(b.center))));
        inconsistent += !(alpha <= 2 * theta + 1e-3);
        inconsistent += std::abs(glm::length(b.axis) - 1.0f) > 1e-5f;
        inconsistent += std::abs(b.cos_angle * b.cos_angle + b.sin_angle * b.sin_angle - 1.0f) > 1e-5f;
    }
    CHECK(inconsistent == 0);
    std::sort(ratios.begin(), ratios.end());
    std::sort(angles.begin(), angles.end());
    INFO("radius / disk radius: median " << ratios[ratios.size() / 2] << ", max " << ratios.back());
    INFO("cone half-angle (deg): median " << angles[angles.size() / 2] * 180 / M_PI << ", max "
                                          << angles.back() * 180 / M_PI);
    // Measured: median 1.5, max 3.0; half-angle median 10 deg, max 20 deg.
    CHECK(ratios[ratios.size() / 2] < 2.0);
    CHECK(ratios.back() < 3.5);
    // The half-angle of a disk of radius 2 * disk on the unit sphere is asin(0.22) = 13 deg.
    CHECK(angles[angles.size() / 2] < std::asin(2.0 * disk));
    CHECK(angles.back() < 2 * std::asin(std::min(1.0, 3.5 * disk)));
}

TEST_CASE("cluster bounds contain every vertex and normal of their cluster", "[geometry][clusters]") {
    const Mesh m = make_jittered_sphere(2.0f, 4, 0.9f, 3);
    const std::vector<glm::vec3> normals = normals_of(m);
    const FaceClusters cl = cluster_faces(m, 40);
    const std::vector<ClusterBounds> bounds = compute_cluster_bounds(m, normals, cl);
    const Samples s = samples_of(m, normals, cl);
    size_t outside = 0;
    for (size_t c = 0; c < cl.size(); ++c) {
        const ClusterBounds& b = bounds[c];
        for (const auto& [p, n] : s.of_cluster[c]) {
            outside += glm::length(p - glm::dvec3(b.center)) > b.radius * (1 + 1e-6);
            const double cos_to_axis = glm::dot(glm::normalize(n), glm::dvec3(b.axis));
            outside += cos_to_axis < double(b.cos_angle) - 1e-6;
        }
    }
    CHECK(outside == 0);
}

TEST_CASE("classify_facing is never wrong: icosphere, torus, jittered sphere", "[geometry][clusters]") {
    const Mesh meshes[] = {make_icosphere(1.0f, 5), make_torus(1.0f, 0.3f, 120, 40),
                           make_jittered_sphere(1.0f, 5, 1.0f, 11), make_uv_sphere(0.5f, 40, 60)};
    uint32_t seed = 1;
    for (const Mesh& m : meshes)
        for (uint32_t max_faces : {16u, 256u}) {
            const FacingCounts counts = check_mesh(m, normals_of(m), max_faces, seed++);
            INFO("faces " << m.face_count() << ", max_faces " << max_faces << ": front " << counts.front << ", back "
                          << counts.back << ", mixed " << counts.mixed);
            CHECK(counts.wrong == 0);
            CHECK(counts.front > 0);  // the check is not vacuous
            CHECK(counts.back > 0);
        }
}

TEST_CASE("classify_facing is never wrong: bunny, far from the origin, unnormalised normals",
          "[geometry][clusters]") {
    const Mesh bunny = load_mesh(test::shared_mesh("bunny.ply"));
    const std::vector<glm::vec3> bunny_normals = normals_of(bunny);
    {
        const FacingCounts counts = check_mesh(bunny, bunny_normals, 256, 21);
        INFO("front " << counts.front << ", back " << counts.back << ", mixed " << counts.mixed);
        CHECK(counts.wrong == 0);
        CHECK(counts.front > 0);
        CHECK(counts.back > 0);
    }
    // Normals of random lengths: only their directions count.
    std::vector<glm::vec3> scaled = bunny_normals;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> scale(1e-3f, 1e3f);
    for (glm::vec3& n : scaled) n *= scale(rng);
    CHECK(check_mesh(bunny, scaled, 64, 22).wrong == 0);

    // Coordinates far from the origin, where eye - p loses digits.
    Mesh far = make_icosphere(1.0f, 4);
    for (glm::vec3& p : far.positions) p += glm::vec3(1000.0f, -2000.0f, 500.0f);
    const FacingCounts counts = check_mesh(far, normals_of(far), 32, 23);
    CHECK(counts.wrong == 0);
    CHECK(counts.front + counts.back > 0);
}

TEST_CASE("classify_facing culls most of a sphere seen from afar", "[geometry][clusters]") {
    const Mesh m = make_icosphere(1.0f, 6);
    const std::vector<ClusterBounds> bounds = compute_cluster_bounds(m, normals_of(m), cluster_faces(m, 256));
    for (glm::vec3 dir : {glm::vec3(0, 0, 1), glm::vec3(0.6f, 0.8f, 0), glm::vec3(0.48f, 0.6f, 0.64f)}) {
        // From distance d (radius 1) the front-facing cap is (1 - 1/d) / 2 of the
        // sphere: a third at d = 3, so Front cannot reach 35% there; at d = 10, 45%.
        // Only a band of clusters around the silhouette circle may be Mixed.
        const auto [front3, back3] = front_back_fractions(bounds, 3.0f * dir);
        INFO("d = 3: front " << front3 << ", back " << back3);  // measured 0.23, 0.54
        CHECK(front3 >= 0.2);
        CHECK(back3 >= 0.45);
        const auto [front10, back10] = front_back_fractions(bounds, 10.0f * dir);
        INFO("d = 10: front " << front10 << ", back " << back10);  // measured 0.36, 0.45
        CHECK(front10 >= 0.3);
        CHECK(back10 >= 0.35);
    }
}

TEST_CASE("face clusters and bounds on degenerate meshes", "[geometry][clusters]") {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},     // a quad: faces 0, 1
                   {0.5f, -1, 0.5f}, {0.5f, -1, -0.5f},            // two fins on edge (0, 1): non-manifold
                   {2, 0, 0}, {3, 0, 0}, {4, 0, 0},                // collinear: zero area
                   {7, 7, 7}, {-7, 7, 7},                          // isolated vertices
                   {10, 0, 0}, {11, 0, 0}, {10, 1, 0}};            // a second component
    m.faces = {{0, 1, 2}, {1, 3, 2}, {0, 1, 4}, {1, 0, 5},  // three faces on edge (0, 1)
               {6, 7, 8},                                   // zero area
               {1, 1, 3},                                   // repeated index
               {11, 12, 13}, {11, 11, 11}};                 // another component, a point face
    const std::vector<glm::vec3> normals = normals_of(m);
    for (uint32_t max_faces : {1u, 2u, 3u, 256u}) {
        INFO("max_faces " << max_faces);
        const FaceClusters cl = cluster_faces(m, max_faces);
        check_partition(m, cl, max_faces);
        CHECK(disconnected_clusters(m, cl) == 0);
        const std::vector<ClusterBounds> bounds = compute_cluster_bounds(m, normals, cl);
        REQUIRE(bounds.size() == cl.size());
        for (const ClusterBounds& b : bounds) {
            const float values[] = {b.center.x, b.center.y, b.center.z, b.radius, b.axis.x,
                                    b.axis.y,   b.axis.z,   b.cos_angle, b.sin_angle};
            for (float v : values) CHECK(std::isfinite(v));
            CHECK(b.radius >= 0);
        }
        // The vertices of the zero-area face have zero normals (vertex_basics.h): its
        // cluster is "all directions".
        for (size_t c = 0; c < cl.size(); ++c)
            for (uint32_t i = cl.cluster_start[c]; i < cl.cluster_start[c + 1]; ++i)
                if (cl.face_order[i] == 4) CHECK(bounds[c].cos_angle == -1);
        const Samples s = samples_of(m, normals, cl);
        FacingCounts counts;
        for (glm::vec3 eye : {glm::vec3(0.3f, 0.3f, 5), glm::vec3(0.3f, 0.3f, -5), glm::vec3(10.2f, 0.2f, 3),
                              glm::vec3(10.2f, 0.2f, -3), glm::vec3(0, 0, 0), glm::vec3(100, 50, 20)})
            check_eye(bounds, s, eye, counts);
        CHECK(counts.wrong == 0);
        if (max_faces == 1) CHECK(counts.front + counts.back > 0);
    }
}

TEST_CASE("cluster bounds: a non-finite position makes its cluster never culled", "[geometry][clusters]") {
    Mesh m = make_icosphere(1.0f, 3);
    const std::vector<glm::vec3> normals = normals_of(m);  // finite, computed before the damage
    m.positions[17] = glm::vec3(NAN, 0.5f, 0.5f);
    m.positions[42] = glm::vec3(0.5f, INFINITY, 0.5f);
    const FaceClusters cl = cluster_faces(m, 16);
    const std::vector<ClusterBounds> bounds = compute_cluster_bounds(m, normals, cl);
    size_t damaged = 0;
    for (size_t c = 0; c < cl.size(); ++c) {
        bool has_bad_vertex = false;
        for (uint32_t i = cl.cluster_start[c]; i < cl.cluster_start[c + 1]; ++i)
            for (int j = 0; j < 3; ++j) {
                const uint32_t v = m.faces[cl.face_order[i]][j];
                has_bad_vertex |= v == 17 || v == 42;
            }
        if (!has_bad_vertex) continue;
        ++damaged;
        CHECK(bounds[c].cos_angle == -1);
        CHECK(std::isinf(bounds[c].radius));
        for (glm::vec3 eye : {glm::vec3(0, 0, 5), glm::vec3(0, 0, -5), glm::vec3(3, 4, 0)})
            CHECK(classify_facing(bounds[c], eye) == Facing::Mixed);
    }
    CHECK(damaged >= 2);
}
