// Embree 3 acceleration structure for the CPU reference: one Embree scene per mesh (built once,
// however many instances use it) and a top-level scene of Embree instance geometries whose
// geometry IDs are the FlatScene instance indices.
#pragma once

#include "scene/flatten.h"
#include "shared/path.h"

#include <embree3/rtcore.h>

#include <atomic>
#include <vector>

namespace tp {

struct Hit {
    bool found = false;
    float t = 0.0f;
    uint32_t instance = 0;
    uint32_t primitive = 0;
    vec2 bary{0.0f}; // weights of vertices 1 and 2, as surface_point() expects
};

class EmbreeAccel {
  public:
    explicit EmbreeAccel(const FlatScene& scene);
    ~EmbreeAccel();
    EmbreeAccel(const EmbreeAccel&) = delete;
    EmbreeAccel& operator=(const EmbreeAccel&) = delete;

    Hit intersect(const Ray& ray) const;
    bool occluded(const Ray& ray) const;

    // Bytes Embree holds for the acceleration structures (its memory monitor).
    uint64_t memory_bytes() const { return uint64_t(std::max<int64_t>(bytes_.load(), 0)); }

  private:
    RTCDevice device_ = nullptr;
    RTCScene top_ = nullptr;
    std::vector<RTCScene> meshes_;
    std::atomic<int64_t> bytes_{0};
    static bool monitor(void* self, ssize_t bytes, bool post);
    void check(const char* what) const;
};

} // namespace tp
