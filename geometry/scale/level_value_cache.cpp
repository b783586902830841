#include "level_value_cache.h"

#include <algorithm>

namespace kappa {

LevelValueCache& LevelValueCache::operator=(const LevelValueCache& other) {
    if (this != &other) {
        levels_.clear();
        floats_ = other.floats_, enabled_ = other.enabled_, budget_ = other.budget_;
    }
    return *this;
}

void LevelValueCache::enable(bool on) {
    enabled_ = on;
    if (!on) levels_.clear();
}

size_t LevelValueCache::default_budget_bytes() {
#ifdef __EMSCRIPTEN__
    return size_t(256) << 20;  // a page's whole memory is a few GiB at most
#else
    return size_t(5) << 29;  // 2.5 GiB: three levels of the curvature blend's for a 9M-vertex mesh
#endif
}

size_t LevelValueCache::bytes() const {
    size_t kept = 0;
    for (const Level& l : levels_)
        if (l.values) kept += level_bytes(vertices_);
    return kept;
}

void LevelValueCache::prepare(size_t levels, size_t vertices, size_t first, size_t last,
                              const std::vector<bool>& fitted) {
    if (!enabled_) return;
    if (vertices != vertices_ || levels != levels_.size()) {  // another mesh or space: start again
        levels_.clear();
        levels_.resize(levels);
        vertices_ = vertices;
    }
    ++clock_;
    const size_t per_level = level_bytes(vertices);
    for (size_t l = first; l <= last && l < levels; ++l) {
        if (!fitted[l]) continue;
        Level& level = levels_[l];
        level.used = clock_;
        if (level.values) continue;
        // Room: drop the least recently used levels this blend does not read.
        while (bytes() + per_level > budget_) {
            Level* oldest = nullptr;
            for (Level& other : levels_)
                if (other.values && other.used < clock_ && (!oldest || other.used < oldest->used)) oldest = &other;
            if (!oldest) break;
            oldest->values.reset(), oldest->states.reset();
        }
        if (bytes() + per_level > budget_) continue;  // blended without the cache
        level.values.reset(new float[vertices * floats_]);  // left uninitialised: the states say
        level.states.reset(new uint8_t[vertices]());
    }
}

}  // namespace kappa
