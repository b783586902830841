#include "vertex_weld.h"

#include <cstdint>
#include <cstring>

namespace kappa::io {

namespace {

struct Key {
    uint32_t bits[3];
    bool operator==(const Key& o) const {
        return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
    }
};

Key key_of(const glm::vec3& p) {
    Key k;
    for (int a = 0; a < 3; ++a) {
        float v = p[a] + 0.0f;  // -0 + 0 = +0: equal values give equal bits
        std::memcpy(&k.bits[a], &v, 4);
    }
    return k;
}

uint64_t hash_of(const Key& k) {
    // 64-bit mix (splitmix64 finaliser) of the three coordinate bit patterns.
    uint64_t h = (uint64_t(k.bits[0]) << 32 | k.bits[1]) ^ (uint64_t(k.bits[2]) * 0x9e3779b97f4a7c15ULL);
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    h ^= h >> 31;
    return h;
}

}  // namespace

Mesh weld_exact(const std::vector<glm::vec3>& corners) {
    Mesh mesh;
    // Open addressing with linear probing; slots hold vertex index + 1.
    size_t capacity = 16;
    while (capacity < corners.size() * 2) capacity *= 2;
    std::vector<uint32_t> slots(capacity, 0);
    std::vector<Key> keys;
    keys.reserve(corners.size() / 4);
    mesh.positions.reserve(corners.size() / 4);
    mesh.faces.reserve(corners.size() / 3);

    uint32_t corner[3];
    for (size_t i = 0; i < corners.size(); ++i) {
        Key k = key_of(corners[i]);
        size_t s = size_t(hash_of(k)) & (capacity - 1);
        while (slots[s] != 0 && !(keys[slots[s] - 1] == k)) s = (s + 1) & (capacity - 1);
        if (slots[s] == 0) {
            keys.push_back(k);
            mesh.positions.push_back(corners[i]);
            slots[s] = uint32_t(keys.size());
        }
        corner[i % 3] = slots[s] - 1;
        if (i % 3 == 2) mesh.faces.emplace_back(corner[0], corner[1], corner[2]);
    }
    return mesh;
}

}  // namespace kappa::io
