#include "bench/scene_hash.h"

#include "bench/renderer_version.h"

#include <fmt/format.h>

#include <vector>

namespace tp::bench {
namespace {

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
    template <typename T>
    void array(const std::vector<T>& v) {
        value(uint64_t(v.size()));
        bytes(v.data(), v.size() * sizeof(T));
    }
    uint64_t get() const { return h_; }

  private:
    uint64_t h_ = 14695981039346656037ull;
};

} // namespace

uint64_t hash_flat_scene(const FlatScene& s) {
    Fnv1a h;
    h.value(s.params);
    h.value(s.spp);
    h.array(s.materials);
    h.array(s.meshes);
    h.array(s.positions);
    h.array(s.normals);
    h.array(s.uvs);
    h.array(s.triangles);
    h.array(s.instances);
    h.array(s.lights);
    h.array(s.light_table);
    h.array(s.textures);
    h.array(s.texels);
    h.array(s.env_table);
    return h.get();
}

std::string renderer_version() {
    return fmt::format("{}+{}", TWINPATH_VERSION, TWINPATH_RENDERER_HASH);
}

} // namespace tp::bench
