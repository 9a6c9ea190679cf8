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
    return {&CpuIntegrator::radiance_for<fixed_subset(uint32_t(I))>...};
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

template <uint32_t Fixed, bool Record>
vec3 CpuIntegrator::trace_path(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays,
                               std::vector<PathVertex>* log) const {
    CpuEngine<Fixed, Record> engine(state_, accel_, features_, log);
    return engine.path_radiance(x, y, sample_index, rays);
}

template <uint32_t Fixed>
vec3 CpuIntegrator::radiance_for(uint32_t x, uint32_t y, uint32_t sample_index,
                                 RayCounts& rays) const {
    return trace_path<Fixed, false>(x, y, sample_index, rays, nullptr);
}

vec3 CpuIntegrator::record(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays,
                           std::vector<PathVertex>& log) const {
    return trace_path<kCpuFixedFeatures, true>(x, y, sample_index, rays, &log);
}

} // namespace tp
