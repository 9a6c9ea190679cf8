// One pixel's share of a batch: its samples traced in order, NaN/Inf samples counted and
// dropped (DESIGN.md, "No silent NaN"), the rest summed in double precision into the pixel's
// accumulator; and the ray counters. Shared by every entry point (compute, ray generation).
//
// Precision: each sample is added to a double sum and sum of squares, so after n samples the
// relative rounding error of either is below n * 2^-53 (1e-10 at n = 10^6) and the variance
// that the host derives from them (sum_sq - sum * mean) keeps ~6 significant digits even when
// the pixel's mean is 10^3 times its standard deviation.
#ifndef TP_SHADERS_ACCUMULATE_GLSL
#define TP_SHADERS_ACCUMULATE_GLSL

#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require

#include "integrator.glsl"

struct PixelCounts {
    RayCounts rays;
    uint nan;
};

PixelCounts pixel_counts_zero() {
    PixelCounts c;
    c.rays.camera = 0u;
    c.rays.extension = 0u;
    c.rays.shadow = 0u;
    c.nan = 0u;
    return c;
}

PixelCounts render_pixel(uvec2 pixel) {
    PixelCounts c = pixel_counts_zero();
    dvec3 sum = dvec3(0.0);
    dvec3 sum_sq = dvec3(0.0);
    uint n = 0u;
    for (uint s = 0u; s < batch.sample_count; ++s) {
        vec3 L = path_radiance(pixel.x, pixel.y, batch.sample_begin + s, c.rays);
        if (!is_finite3(L)) {
            ++c.nan;
            continue;
        }
        dvec3 d = dvec3(L);
        sum += d;
        sum_sq += d * d;
        ++n;
    }
    uint p = pixel.y * params.camera.width + pixel.x;
    accum[p].sum += sum;
    accum[p].sum_sq += sum_sq;
    accum[p].count += n;
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
    if (subgroupElect()) {
        counter_add(COUNTER_CAMERA, camera);
        counter_add(COUNTER_EXTENSION, extension);
        counter_add(COUNTER_SHADOW, shadow);
        counter_add(COUNTER_NAN, nan);
    }
}

#endif // TP_SHADERS_ACCUMULATE_GLSL
