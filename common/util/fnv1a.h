// 64-bit FNV-1a (Fowler, Noll & Vo; IETF draft-eastlake-fnv): the hash of the project's cache
// keys and fingerprints (the scene hash, the bench reference cache, the pipeline cache). Fast
// and well spread, not cryptographic: it tells apart inputs, it does not defend against forged
// ones. The bytes of a value are hashed as they lie in memory, so a key is valid on the machine
// (byte order) that wrote it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tp {

constexpr uint64_t kFnv1aOffsetBasis = 0xcbf29ce484222325ull;
constexpr uint64_t kFnv1aPrime = 0x100000001b3ull;

// The hash of `bytes` bytes at `data`, continuing from `h` (the offset basis for a new hash).
inline uint64_t fnv1a64(const void* data, size_t bytes, uint64_t h = kFnv1aOffsetBasis) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * kFnv1aPrime;
    return h;
}

// The same hash fed piece by piece.
class Fnv1a {
  public:
    void bytes(const void* data, size_t n) { h_ = fnv1a64(data, n, h_); }
    template <typename T>
    void value(const T& v) {
        bytes(&v, sizeof v);
    }
    // The length first, so that moving an element from one array to the next changes the hash.
    template <typename T>
    void array(const std::vector<T>& v) {
        value(uint64_t(v.size()));
        bytes(v.data(), v.size() * sizeof(T));
    }
    uint64_t get() const { return h_; }

  private:
    uint64_t h_ = kFnv1aOffsetBasis;
};

} // namespace tp
