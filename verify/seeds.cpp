#include "verify/seeds.h"

#include <algorithm>

namespace tp {
namespace {

// MurmurHash3's 32-bit finalizer (Appleby): a bijection of uint32 whose output bits each depend
// on every input bit.
uint32_t fmix32(uint32_t h) {
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

uint32_t derived(uint32_t seed, uint32_t role) {
    return fmix32(fmix32(seed) ^ fmix32(0x9e3779b9u * (role + 1u)));
}

} // namespace

VerifySeeds verify_seeds(uint32_t seed, const std::vector<std::optional<uint32_t>>& own) {
    VerifySeeds s;
    std::vector<uint32_t> taken;
    for (const std::optional<uint32_t>& o : own)
        if (o) taken.push_back(*o);
    uint32_t role = 0;
    // The next derived seed that no engine owns and none was given before.
    auto fresh = [&] {
        for (;;) {
            const uint32_t v = derived(seed, role++);
            if (std::find(taken.begin(), taken.end(), v) == taken.end()) {
                taken.push_back(v);
                return v;
            }
        }
    };
    for (const std::optional<uint32_t>& o : own) s.image.push_back(o ? *o : fresh());
    for (const std::optional<uint32_t>& o : own) s.pilot.push_back(o ? *o : fresh());
    s.log = s.image.front();
    return s;
}

} // namespace tp
