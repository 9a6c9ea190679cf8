// The CPU reference path tracer: the shared path loop (shared/integrator.h) with the CPU
// engine's hooks (cpu_engine.h), one copy per subset of kCpuFixedFeatures, the copy for the
// render's feature mask picked once.
#pragma once

#include "cpu_ref/cpu_engine.h"
#include "cpu_ref/embree_accel.h"
#include "render/stats.h"
#include "shared/path_log.h"

#include <array>
#include <utility>
#include <vector>

// The path loop is compiled twice, for baseline x86-64 and for x86-64-v3 (AVX2, FMA, BMI2), and
// the dynamic loader picks the second where the CPU has it (GCC's function multiversioning, an
// ifunc): the reference still runs on any x86-64 and is faster where it can (BENCHMARKS.md).
// `flatten` inlines the whole loop (path_radiance and what it calls) into each copy: without it
// GCC keeps path_radiance out of line, compiled once for baseline x86-64, and the x86-64-v3 copy
// is only a wrapper around it. integrator.cpp is compiled with -ffp-contract=off
// (cpu_ref/CMakeLists.txt): neither copy fuses a multiply-add, so both give bit-identical images.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TP_PATH_LOOP_CLONES __attribute__((flatten, target_clones("default", "arch=x86-64-v3")))
#else
#define TP_PATH_LOOP_CLONES
#endif

namespace tp {

class CpuIntegrator {
  public:
    // `features`: the feature mask the path loop is specialized to (shared/features.h); it
    // must include every feature of the scene (FEATURES_ALL always does). `seed`, `sampler`: the
    // render's (shared/rng.h).
    CpuIntegrator(const FlatScene& scene, const EmbreeAccel& accel, uint32_t features,
                  uint32_t seed, uint32_t sampler = SAMPLER_RANDOM);

    // Radiance estimate of sample `sample_index` of pixel (x, y); rays are counted into `rays`.
    vec3 radiance(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays) const {
        return (this->*loop_)(x, y, sample_index, rays);
    }

    // The same sample with every vertex appended to `log` (path logs, shared/path_log.h): the
    // loop with every material feature compiled in and recording on.
    vec3 record(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays,
                std::vector<PathVertex>& log) const;

  private:
    // The path loop compiled for the feature bits `Fixed` (a subset of kCpuFixedFeatures).
    template <uint32_t Fixed>
    vec3 radiance_for(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays) const;
    // The loop itself, in the two instruction-set copies; Record: append a PathVertex per
    // vertex to *log.
    template <uint32_t Fixed, bool Record>
    TP_PATH_LOOP_CLONES vec3 trace_path(uint32_t x, uint32_t y, uint32_t sample_index,
                                        RayCounts& rays, std::vector<PathVertex>* log) const;
    using Loop = vec3 (CpuIntegrator::*)(uint32_t, uint32_t, uint32_t, RayCounts&) const;
    template <size_t... I>
    static std::array<Loop, sizeof...(I)> make_loops(std::index_sequence<I...>);

    CpuSceneState state_;
    const EmbreeAccel& accel_;
    uint32_t features_;
    Loop loop_;
};

} // namespace tp
