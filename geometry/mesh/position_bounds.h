// The axis-aligned bounds of a mesh's points, in parallel blocks: the least
// and greatest coordinates are the same in any order, so the bounds do not
// depend on the thread count.
#pragma once

#include <glm/vec3.hpp>
#include <glm/ext/vector_double3.hpp>

#include <limits>
#include <vector>

namespace kappa {

struct PositionBounds {
    glm::vec3 lo{std::numeric_limits<float>::infinity()}, hi{-std::numeric_limits<float>::infinity()};
    bool empty() const { return !(lo.x <= hi.x); }  // no finite point
    glm::vec3 center() const {  // the origin for empty bounds
        return empty() ? glm::vec3(0.0f) : glm::vec3(0.5 * (glm::dvec3(lo) + glm::dvec3(hi)));
    }
};

// Points with a non-finite coordinate are left out.
PositionBounds position_bounds(const std::vector<glm::vec3>& positions);

}  // namespace kappa
