// The parallel radix select (geometry/parallel/select_value.h) gives exactly
// what std::nth_element gives on the values it counts, whatever the thread
// count: medians and percentiles of every view depend on it.
#include "geometry/parallel/select_value.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace kappa;

namespace {

// nth_element over the counted values (>= 0, not NaN).
float reference(const std::vector<float>& values, double fraction) {
    std::vector<float> kept;
    for (float v : values)
        if (v >= 0.0f) kept.push_back(v);
    if (kept.empty()) return std::nanf("");
    const size_t k = std::min(kept.size() - 1, size_t(fraction * double(kept.size())));
    std::nth_element(kept.begin(), kept.begin() + std::ptrdiff_t(k), kept.end());
    return kept[k];
}

float selected(const std::vector<float>& values, double fraction) {
    return select_nonnegative(
        values.size(), [&](size_t i) { return values[i]; },
        [fraction](size_t m) { return size_t(fraction * double(m)); });
}

}  // namespace

TEST_CASE("radix select equals nth_element on the non-negative values, any thread count", "[parallel]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::lognormal_distribution<float> spread(0.0f, 4.0f);  // many binades, as curvature radii
    const float inf = std::numeric_limits<float>::infinity();
    for (size_t n : {size_t(1), size_t(2), size_t(1000), size_t(300001)}) {
        std::vector<float> values(n);
        for (size_t i = 0; i < n; ++i) {
            const float u = uniform(rng);
            // Duplicates, zeros of both signs, infinities, NaN and negatives (left out).
            values[i] = u < 0.05f ? 0.0f : u < 0.07f ? -0.0f : u < 0.08f ? inf : u < 0.09f ? std::nanf("")
                      : u < 0.12f ? -spread(rng) : u < 0.2f ? 0.25f : spread(rng);
        }
        for (double fraction : {0.0, 0.01, 0.5, 0.98, 1.0}) {
            const float want = reference(values, fraction);
            for (unsigned threads : {1u, 2u, 5u}) {
                set_thread_count(threads);
                const float got = selected(values, fraction);
                INFO("n " << n << ", fraction " << fraction << ", threads " << threads);
                if (std::isnan(want)) CHECK(std::isnan(got));
                else CHECK(got == want);
            }
        }
    }
    set_thread_count(0);
}

TEST_CASE("radix select of nothing counted is NaN", "[parallel]") {
    const std::vector<float> none = {-1.0f, std::nanf(""), -0.5f};
    CHECK(std::isnan(selected(none, 0.5)));
    CHECK(std::isnan(selected({}, 0.5)));
}
