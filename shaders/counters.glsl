// The ray and sample counters of interface.h (COUNTER_*), summed per subgroup so that one
// invocation per subgroup touches memory: the render shaders' ray counts, the resolve pass's
// NaN samples and cut-short pixel slots.
#ifndef TP_SHADERS_COUNTERS_GLSL
#define TP_SHADERS_COUNTERS_GLSL

#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require

#include "bindings.glsl"

// Adds to a 64-bit counter kept as (low, high) words: a per-call value below 2^32 can carry
// at most once.
void counter_add(uint slot, uint value) {
    if (value == 0u) return;
    uint old = atomicAdd(counters[slot], value);
    if (old + value < old) atomicAdd(counters[slot + 1u], 1u);
}

// Call from uniform control flow (every invocation of the subgroup).
void counters_flush(uint camera, uint extension, uint shadow, uint nan, uint truncated) {
    camera = subgroupAdd(camera);
    extension = subgroupAdd(extension);
    shadow = subgroupAdd(shadow);
    nan = subgroupAdd(nan);
    truncated = subgroupAdd(truncated);
    if (subgroupElect()) {
        counter_add(COUNTER_CAMERA, camera);
        counter_add(COUNTER_EXTENSION, extension);
        counter_add(COUNTER_SHADOW, shadow);
        counter_add(COUNTER_NAN, nan);
        counter_add(COUNTER_TRUNCATED, truncated);
    }
}

#endif // TP_SHADERS_COUNTERS_GLSL
