// Disjoint sets over 0..n-1 (union by size, path halving): near-constant
// time per operation. Used for connected components and boundary loops.
#pragma once

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace kappa {

class UnionFind {
public:
    explicit UnionFind(size_t n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), 0u); }

    uint32_t find(uint32_t x) {
        while (parent_[x] != x) {
            parent_[x] = parent_[parent_[x]];
            x = parent_[x];
        }
        return x;
    }

    // x's root without shortening paths: callable from several threads at once while none unites.
    uint32_t root(uint32_t x) const {
        while (parent_[x] != x) x = parent_[x];
        return x;
    }

    // Returns true when a and b were in different sets.
    bool unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        if (size_[a] < size_[b]) std::swap(a, b);
        parent_[b] = a;
        size_[a] += size_[b];
        return true;
    }

private:
    std::vector<uint32_t> parent_, size_;
};

}  // namespace kappa
