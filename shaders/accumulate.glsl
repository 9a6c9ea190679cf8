// One pixel's share of a batch: its samples traced in order, NaN/Inf samples counted and
// dropped (DESIGN.md, "No silent NaN"), the rest summed in double precision into the pixel's
// accumulator; and the ray counters. Shared by every entry point (compute, ray generation).
//
// Precision: each sample is added to a double sum and sum of squares, so after n samples the
// relative rounding error of either is below n * 2^-53 (1e-10 at n = 10^6) and the variance
// that the host derives from them (sum_sq - sum * mean) keeps ~6 significant digits even when
// the pixel's mean is 10^3 times its standard deviation.
//
// Loop budget: Mesa's llvmpipe (lavapipe, the CI device) ends every loop of a SIMD group once
// all its loops together have iterated 65535 times (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS, a
// counter that is never reset), which would silently cut a BVH traversal or a path short.
// After each sample, a loop of exactly batch.probe_iterations iterations checks that the
// budget held while the sample ran (once it is spent, every loop runs exactly once). Only then
// is the sample kept; otherwise the pixel stops at that sample, and the host repeats the
// dispatch, which resumes every slot of every pixel at its next_sample. Every sample index is
// thus traced to completion exactly once, whatever the device. Elsewhere the probe always
// passes.
#ifndef TP_SHADERS_ACCUMULATE_GLSL
#define TP_SHADERS_ACCUMULATE_GLSL

#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require

#include "integrator.glsl"

struct PixelCounts {
    RayCounts rays;
    uint nan;
    uint truncated; // 1 when the pixel stopped before the batch's last sample
};

PixelCounts pixel_counts_zero() {
    PixelCounts c;
    c.rays.camera = 0u;
    c.rays.extension = 0u;
    c.rays.shadow = 0u;
    c.nan = 0u;
    c.truncated = 0u;
    return c;
}

bool loop_budget_held() {
    uint n = 0u;
    for (uint i = 0u; i < batch.probe_iterations; ++i) ++n;
    return n == batch.probe_iterations;
}

// The pixel's samples in [batch.sample_begin, end), slot by slot: slot b (one per Sobol batch,
// interface.h; the only one with the random sampler) takes the samples s = b mod slots in
// increasing order, in registers, and is read and written once, so a sample costs no memory
// traffic whatever the sampler. Each slot keeps its own next_sample (the next index of its
// residue class still to trace), so a dispatch cut short resumes every slot where it stopped.
// The running sums continue the slot's, so a slot's samples are added to one double sum in
// sample order however the render is split into batches and repeated dispatches: the batch
// planner follows measured time, and the same seed must still give the same bits.
PixelCounts render_pixel(uvec2 pixel) {
    PixelCounts c = pixel_counts_zero();
    uint slots = accum_slots(params.sampler_id);
    uint first = (pixel.y * params.camera.width + pixel.x) * slots;
    uint end = batch.sample_begin + batch.sample_count;
    bool held = true;
    for (uint b = 0u; b < slots && held; ++b) {
        uint a = first + b;
        // next_sample is 0 in a fresh accumulator, below a --sample-offset render's first
        // sample; then up to the first index of the slot's class.
        uint s = max(accum[a].next_sample, batch.sample_begin);
        s += (b + slots - s % slots) % slots;
        dvec3 sum = accum[a].sum;
        dvec3 sum_sq = accum[a].sum_sq;
        uint n = accum[a].count;
        for (; s < end; s += slots) {
            RayCounts rays;
            rays.camera = 0u;
            rays.extension = 0u;
            rays.shadow = 0u;
#ifdef TP_DEBUG_SHADER
            vec3 L = debug_header.integrator == INTEGRATOR_PATH
                         ? path_radiance(pixel.x, pixel.y, s, rays)
                         : debug_view_radiance(pixel.x, pixel.y, s);
#else
            vec3 L = path_radiance(pixel.x, pixel.y, s, rays);
#endif
            if (!loop_budget_held()) { // sample s is discarded and traced again
                held = false;
                break;
            }
            c.rays.camera += rays.camera;
            c.rays.extension += rays.extension;
            c.rays.shadow += rays.shadow;
            if (!is_finite3(L)) {
                ++c.nan;
                continue;
            }
            dvec3 d = dvec3(L);
            sum += d;
            sum_sq += d * d;
            ++n;
        }
        accum[a].sum = sum;
        accum[a].sum_sq = sum_sq;
        accum[a].count = n;
        accum[a].next_sample = s;
    }
    c.truncated = held ? 0u : 1u;
    return c;
}

// Adds to a 64-bit counter kept as (low, high) words: a per-call value below 2^32 can carry
// at most once.
void counter_add(uint slot, uint value) {
    if (value == 0u) return;
    uint old = atomicAdd(counters[slot], value);
    if (old + value < old) atomicAdd(counters[slot + 1u], 1u);
}

// Sums the subgroup's counts first so that one invocation per subgroup touches memory. Call
// from uniform control flow (every invocation of the subgroup, inside the image or not).
void counters_flush(PixelCounts c) {
    uint camera = subgroupAdd(c.rays.camera);
    uint extension = subgroupAdd(c.rays.extension);
    uint shadow = subgroupAdd(c.rays.shadow);
    uint nan = subgroupAdd(c.nan);
    uint truncated = subgroupAdd(c.truncated);
    if (subgroupElect()) {
        counter_add(COUNTER_CAMERA, camera);
        counter_add(COUNTER_EXTENSION, extension);
        counter_add(COUNTER_SHADOW, shadow);
        counter_add(COUNTER_NAN, nan);
        counter_add(COUNTER_TRUNCATED, truncated);
    }
}

#endif // TP_SHADERS_ACCUMULATE_GLSL
