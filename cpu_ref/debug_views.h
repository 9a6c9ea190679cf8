// The CPU's debug outputs besides path logs (docs/debugging.md): the AOVs of a pixel and the
// debug views (`--integrator normals|albedo|depth|cost`), from the camera ray's first hit, with
// the shared bodies of shared/debug_views.h.
#pragma once

#include "cpu_ref/cpu_engine.h"
#include "cpu_ref/embree_accel.h"
#include "shared/path_log.h"

namespace tp {

class CpuDebugViews {
  public:
    CpuDebugViews(const FlatScene& scene, const EmbreeAccel& accel, uint32_t integrator,
                  uint32_t seed, uint32_t sampler = SAMPLER_RANDOM)
        : state_(scene, seed, sampler), accel_(accel), integrator_(integrator) {}

    // AOVs of the ray's first hit (PixelAov of shared/path_log.h).
    PixelAov primary_aov(const Ray& ray) const;

    // The view's value for sample `sample_index` of pixel (x, y), the camera ray jittered as
    // the path loop jitters it. Cost: the nanoseconds Embree's rtcIntersect1 took for the
    // camera ray, in all three channels (Embree exposes no traversal counts).
    vec3 radiance(uint32_t x, uint32_t y, uint32_t sample_index) const;

  private:
    using Engine = CpuEngine<kCpuFixedFeatures, false>;
    CpuSceneState state_;
    const EmbreeAccel& accel_;
    uint32_t integrator_;
};

} // namespace tp
