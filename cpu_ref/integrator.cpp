#include "cpu_ref/integrator.h"

#include <array>
#include <utility>

namespace tp {
namespace {

// The i-th subset of kCpuFixedFeatures (bit j of i selects its j-th set bit).
constexpr uint32_t fixed_subset(uint32_t i) {
    uint32_t out = 0, j = 0;
    for (uint32_t bit = 1; bit <= kCpuFixedFeatures; bit <<= 1)
        if (kCpuFixedFeatures & bit) {
            if (i & (1u << j)) out |= bit;
            ++j;
        }
    return out;
}

constexpr uint32_t kFixedCount = 1u << 5;
static_assert(fixed_subset(kFixedCount - 1) == kCpuFixedFeatures, "five fixed bits");

} // namespace

template <size_t... I>
std::array<CpuIntegrator::Loop, sizeof...(I)> CpuIntegrator::make_loops(std::index_sequence<I...>) {
    return {&CpuIntegrator::group_for<fixed_subset(uint32_t(I))>...};
}

CpuIntegrator::CpuIntegrator(const FlatScene& scene, const EmbreeAccel& accel, uint32_t features,
                             uint32_t seed, uint32_t sampler)
    : state_(scene, seed, sampler), accel_(accel), features_(features) {
    static const std::array<Loop, kFixedCount> loops =
        make_loops(std::make_index_sequence<kFixedCount>{});
    loop_ = loops[0];
    for (uint32_t i = 0; i < kFixedCount; ++i)
        if (fixed_subset(i) == (features & kCpuFixedFeatures)) loop_ = loops[i];
}

template <uint32_t Fixed>
void CpuIntegrator::trace_group(const PixelSample* samples, uint32_t count, vec3* L,
                                RayCounts& rays) const {
    using Engine = CpuEngine<Fixed, false>;
    Engine camera(state_, accel_, features_);
    typename Engine::PathState paths[kGroup];
    Ray camera_rays[kGroup];
    for (uint32_t i = 0; i < count; ++i) {
        paths[i] = camera.path_begin(samples[i].x, samples[i].y, samples[i].sample, rays);
        camera_rays[i] = paths[i].ray;
    }
    Hit hits[kGroup];
    camera.trace_closest_group(camera_rays, count, hits);
    // Each path to its end: path_step's trace, then path_at_hit, written out so that the vertex
    // is inlined once (the camera hit's vertex and the others are the same code).
    for (uint32_t i = 0; i < count; ++i) {
        Engine engine(state_, accel_, features_); // its bounce words are this path's
        Hit hit = hits[i];
        bool found = hit.found;
        while (engine.path_at_hit(paths[i], found, hit, rays))
            found = engine.trace_closest(paths[i].ray, hit);
        L[i] = paths[i].L;
    }
}

template <uint32_t Fixed>
void CpuIntegrator::group_for(const PixelSample* samples, uint32_t count, vec3* L,
                              RayCounts& rays) const {
    trace_group<Fixed>(samples, count, L, rays);
}

vec3 CpuIntegrator::trace_recorded(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays,
                                   std::vector<PathVertex>& log) const {
    CpuEngine<kCpuFixedFeatures, true> engine(state_, accel_, features_, &log);
    return engine.path_radiance(x, y, sample_index, rays);
}

vec3 CpuIntegrator::record(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays,
                           std::vector<PathVertex>& log) const {
    return trace_recorded(x, y, sample_index, rays, log);
}

} // namespace tp
