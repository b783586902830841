// A blend's value of each fitted level at each vertex (scale_space.cpp's
// level_value: the kernel-weighted sums over the vertex's cluster and the
// adjacent ones, the curvature blend's or the surface's), kept once
// computed. They depend on the level and the vertex alone, not on the scale
// a view asks of the vertex: a new view of the same mesh blends them again
// without going back to the clusters (issue 30: a new view of a 17.8M-face
// mesh). 81 bytes a vertex a level for the curvature blend, 33 for the
// surface's; levels are kept within a memory budget (an eighth of the
// machine's memory, at most 2.5 GiB, for the curvature blend's; a third of
// that for the surface's), the least recently used dropped first. Off until
// enabled: a single drawing would only pay for it.
//
// One blend at a time; within a blend each vertex's values are written by
// the one thread that blends it. The values assume the space is always
// blended with the mesh and raw fields it was built from (as ScaleSpace
// does).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace kappa {

class LevelValueCache {
public:
    enum State : uint8_t { Unknown = 0, Usable = 1, Unusable = 2 };

    // Each vertex's value is `floats` floats; levels are kept within `budget` bytes.
    LevelValueCache(size_t floats, size_t budget) : floats_(floats), budget_(budget) {}
    LevelValueCache(const LevelValueCache& other)  // a copy starts empty
        : floats_(other.floats_), enabled_(other.enabled_), budget_(other.budget_) {}
    LevelValueCache& operator=(const LevelValueCache& other);
    LevelValueCache(LevelValueCache&&) noexcept = default;
    LevelValueCache& operator=(LevelValueCache&&) noexcept = default;

    void enable(bool on);
    bool enabled() const { return enabled_; }

    // Before a blend over `vertices` vertices that reads the levels `read` (of `levels`): makes room for
    // them, dropping others beyond the budget, least recently used first. Levels left without room are
    // blended as if there were no cache.
    void prepare(size_t levels, size_t vertices, const std::vector<size_t>& read);
    // The level's values (floats() a vertex) and their states (one a vertex), or null when it has none.
    float* values(size_t level) const { return level < levels_.size() ? levels_[level].values.get() : nullptr; }
    uint8_t* states(size_t level) const { return level < levels_.size() ? levels_[level].states.get() : nullptr; }

    size_t floats() const { return floats_; }
    size_t bytes() const;
    size_t level_bytes(size_t vertices) const { return vertices * (floats_ * sizeof(float) + 1); }
    // The curvature blend's budget: an eighth of the machine's memory, at most 2.5 GiB (three levels
    // of a 9M-vertex mesh).
    static size_t curvature_budget_bytes();
    size_t budget_bytes() const { return budget_; }
    void set_budget_bytes(size_t budget) { budget_ = budget; }

private:
    struct Level {
        std::unique_ptr<float[]> values;  // uninitialised where the state is Unknown
        std::unique_ptr<uint8_t[]> states;
        uint64_t used = 0;
    };
    size_t floats_ = 0;
    bool enabled_ = false;
    size_t budget_ = 0;
    size_t vertices_ = 0;
    uint64_t clock_ = 0;
    std::vector<Level> levels_;
};

}  // namespace kappa
