#include "level_value_cache.h"

#include <algorithm>

#ifndef __EMSCRIPTEN__
#include <unistd.h>
#endif

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

size_t LevelValueCache::curvature_budget_bytes() {
#ifdef __EMSCRIPTEN__
    const size_t memory = size_t(2) << 30;  // a page's whole memory is a few GiB at most
#else
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    const size_t memory = pages > 0 && page > 0 ? size_t(pages) * size_t(page) : size_t(8) << 30;
#endif
    return std::min(memory / 8, size_t(5) << 29);
}

size_t LevelValueCache::bytes() const {
    size_t kept = 0;
    for (const Level& l : levels_)
        if (l.values) kept += level_bytes(vertices_);
    return kept;
}

void LevelValueCache::prepare(size_t levels, size_t vertices, const std::vector<size_t>& read) {
    if (!enabled_) return;
    if (vertices != vertices_ || levels != levels_.size()) {  // another mesh or space: start again
        levels_.clear();
        levels_.resize(levels);
        vertices_ = vertices;
    }
    ++clock_;
    const size_t per_level = level_bytes(vertices);
    for (const size_t l : read) {
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
