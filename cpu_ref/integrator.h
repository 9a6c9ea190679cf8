// The CPU reference path tracer: one path per call, following the per-vertex order documented
// in shared/path.h with Embree for the ray queries.
#pragma once

#include "cpu_ref/embree_accel.h"
#include "cpu_ref/scene_access.h"
#include "render/stats.h"

namespace tp {

class CpuIntegrator {
  public:
    CpuIntegrator(const FlatScene& scene, const EmbreeAccel& accel)
        : access_(scene), accel_(accel) {}

    // Radiance estimate of sample `sample_index` of pixel (x, y); rays are counted into `rays`.
    vec3 radiance(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays) const;

  private:
    SceneAccess access_;
    const EmbreeAccel& accel_;
};

} // namespace tp
