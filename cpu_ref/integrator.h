// The CPU reference path tracer: one path per call, following the per-vertex order documented
// in shared/path.h with Embree for the ray queries.
#pragma once

#include "cpu_ref/embree_accel.h"
#include "cpu_ref/scene_access.h"
#include "render/stats.h"
#include "shared/features.h"
#include "shared/path_log.h"

#include <array>
#include <utility>
#include <vector>

// The path loop is compiled twice, for baseline x86-64 and for x86-64-v3 (AVX2, FMA, BMI2), and
// the dynamic loader picks the second where the CPU has it (GCC's function multiversioning, an
// ifunc): the reference still runs on any x86-64 and is 9-11 % faster per spp on cornell where
// it can (BENCHMARKS.md). integrator.cpp is compiled with -ffp-contract=off
// (cpu_ref/CMakeLists.txt): neither copy fuses a multiply-add, so both give bit-identical
// images (measured: 0 difference on cornell, cornell_glossy, spheres).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TP_PATH_LOOP_CLONES __attribute__((target_clones("default", "arch=x86-64-v3")))
#else
#define TP_PATH_LOOP_CLONES
#endif

namespace tp {

class CpuIntegrator {
  public:
    // `features`: the feature mask the path loop is specialized to (shared/features.h); it
    // must include every feature of the scene (FEATURES_ALL always does).
    CpuIntegrator(const FlatScene& scene, const EmbreeAccel& accel,
                  uint32_t features = FEATURES_ALL);

    // Radiance estimate of sample `sample_index` of pixel (x, y); rays are counted into `rays`.
    vec3 radiance(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays) const {
        return (this->*loop_)(x, y, sample_index, rays);
    }

    // The same sample with every vertex appended to `log` (path logs, shared/path_log.h): the
    // loop with every material feature compiled in and recording on.
    vec3 record(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays,
                std::vector<PathVertex>& log) const;

  private:
    // The path loop compiled for the feature bits `Fixed` (a subset of kFixedFeatures); the
    // other bits come from features_ at run time.
    template <uint32_t Fixed>
    vec3 radiance_for(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays) const;
    // The loop itself; Record: fill a PathVertex per vertex into *log (else nothing of it is
    // compiled).
    template <uint32_t Fixed, bool Record>
    TP_PATH_LOOP_CLONES vec3 trace_path(uint32_t x, uint32_t y, uint32_t sample_index,
                                        RayCounts& rays, std::vector<PathVertex>* log) const;
    using Loop = vec3 (CpuIntegrator::*)(uint32_t, uint32_t, uint32_t, RayCounts&) const;
    template <size_t... I>
    static std::array<Loop, sizeof...(I)> make_loops(std::index_sequence<I...>);

    SceneAccess access_;
    const EmbreeAccel& accel_;
    uint32_t features_;
    Loop loop_;
};

} // namespace tp
