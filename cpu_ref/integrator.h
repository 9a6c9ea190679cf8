// The CPU reference path tracer: the shared path loop (shared/integrator.h) with the CPU
// engine's hooks (cpu_engine.h), one copy per subset of kCpuFixedFeatures, the copy for the
// render's feature mask picked once.
#pragma once

#include "cpu_ref/cpu_engine.h"
#include "cpu_ref/embree_accel.h"
#include "cpu_ref/isa_clones.h"
#include "render/stats.h"
#include "shared/path_log.h"

#include <array>
#include <utility>
#include <vector>

namespace tp {

class CpuIntegrator {
  public:
    // `features`: the feature mask the path loop is specialized to (shared/features.h); it
    // must include every feature of the scene (FEATURES_ALL always does). `seed`, `sampler`: the
    // render's (shared/rng.h).
    CpuIntegrator(const FlatScene& scene, const EmbreeAccel& accel, uint32_t features,
                  uint32_t seed, uint32_t sampler = SAMPLER_RANDOM);

    // A pixel's sample: pixel (x, y), sample index `sample`.
    struct PixelSample {
        uint32_t x, y, sample;
    };
    static constexpr uint32_t kGroup = EmbreeAccel::kPacket;

    // Radiance estimates of up to kGroup samples into L; rays are counted into `rays`. Their camera
    // rays are traced together (CpuEngine::trace_closest_group), then each path to its end, in
    // the group's order, by the shared loop (path_begin, path_at_hit, path_step).
    void radiance_group(const PixelSample* samples, uint32_t count, vec3* L,
                        RayCounts& rays) const {
        (this->*loop_)(samples, count, L, rays);
    }

    // One sample with every vertex appended to `log` (path logs, shared/path_log.h): the loop
    // with every material feature compiled in and recording on, the camera ray traced alone.
    vec3 record(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays,
                std::vector<PathVertex>& log) const;

  private:
    // radiance_group for the feature bits `Fixed` (a subset of kCpuFixedFeatures).
    template <uint32_t Fixed>
    void group_for(const PixelSample* samples, uint32_t count, vec3* L, RayCounts& rays) const;
    // The loops themselves, in the two instruction-set copies (isa_clones.h).
    template <uint32_t Fixed>
    TP_ISA_CLONES void trace_group(const PixelSample* samples, uint32_t count, vec3* L,
                                   RayCounts& rays) const;
    TP_ISA_CLONES vec3 trace_recorded(uint32_t x, uint32_t y, uint32_t sample_index,
                                      RayCounts& rays, std::vector<PathVertex>& log) const;
    using Loop = void (CpuIntegrator::*)(const PixelSample*, uint32_t, vec3*, RayCounts&) const;
    template <size_t... I>
    static std::array<Loop, sizeof...(I)> make_loops(std::index_sequence<I...>);

    CpuSceneState state_;
    const EmbreeAccel& accel_;
    uint32_t features_;
    Loop loop_;
};

} // namespace tp
