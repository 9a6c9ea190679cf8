// Fingerprints of a flattened scene: what a render sees of its scene, so that `twinpath merge`
// can refuse parts of different scenes (docs/farm.md), and the bench reference cache's key.
#pragma once

#include "scene/flatten.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

// 64-bit FNV-1a (Fowler, Noll & Vo; IETF draft-eastlake-fnv), offset basis and prime.
class Fnv1a {
  public:
    void bytes(const void* data, size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 1099511628211ull;
    }
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
    uint64_t h_ = 14695981039346656037ull;
};

// Adds every array both engines render from (materials, meshes, vertices, triangles,
// instances, lights, alias tables, textures) and the environment's parameters; not the camera,
// seed, depths or spp. The shared structs have no implicit padding (shared/types.h pins their
// layout) and flatten() value-initializes their pad fields, so their bytes are their values.
// Positions are camera-relative (FlatScene::origin): a moved camera changes them too.
void add_scene_content(Fnv1a& h, const FlatScene& scene);

// add_scene_content alone, as 16 hexadecimal digits (twinpath:scene_hash).
std::string scene_hash(const FlatScene& scene);

} // namespace tp
