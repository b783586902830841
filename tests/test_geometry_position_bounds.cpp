// position_bounds (geometry/mesh/position_bounds.h): four points at a time in
// lanes, one at a time where a block holds a non-finite coordinate or at a
// block's end; always the least and greatest finite points' coordinates.
#include "geometry/mesh/position_bounds.h"
#include "geometry/parallel/parallel.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace kappa;

namespace {

// The bounds point by point, as the header states them.
PositionBounds bounds_one_by_one(const std::vector<glm::vec3>& points) {
    PositionBounds out;
    for (const glm::vec3& p : points)
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
            for (int k = 0; k < 3; ++k) out.lo[k] = std::min(out.lo[k], p[k]), out.hi[k] = std::max(out.hi[k], p[k]);
    return out;
}

}  // namespace

TEST_CASE("position bounds are the finite points' least and greatest coordinates, whatever the thread count",
          "[bounds]") {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-1e3f, 1e3f);
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    // Sizes around the four-point groups and the 65536-point blocks.
    for (const size_t n : {size_t(1), size_t(3), size_t(4), size_t(7), size_t(65536), size_t(65539), size_t(200003)}) {
        std::vector<glm::vec3> points(n);
        for (glm::vec3& p : points) p = {coordinate(random), coordinate(random), coordinate(random)};
        // Each coordinate's extremes on a point of its own, away from the lanes' first slot.
        if (n > 5) points[n - 2].y = 5e3f, points[n / 2 + 1].z = -5e3f, points[1].x = 4e3f;
        for (int bad = 0; bad < 2; ++bad) {
            if (bad && n > 2) {  // a point beyond every other with one coordinate not finite: left out
                points[n / 3] = {9e3f, inf, -9e3f};
                points[n - 1] = {nan, -9e3f, 9e3f};
            }
            const PositionBounds expected = bounds_one_by_one(points);
            for (const unsigned threads : {1u, 3u}) {
                set_thread_count(threads);
                const PositionBounds got = position_bounds(points);
                CAPTURE(n, bad, threads);
                for (int k = 0; k < 3; ++k) {
                    CHECK(got.lo[k] == expected.lo[k]);
                    CHECK(got.hi[k] == expected.hi[k]);
                }
            }
            set_thread_count(0);
        }
    }
    CHECK(position_bounds({}).empty());
    CHECK(position_bounds({glm::vec3(nan, 0, 0), glm::vec3(0, inf, 0)}).empty());
    CHECK(position_bounds({glm::vec3(1, 2, 3)}).center() == glm::vec3(1, 2, 3));
}
