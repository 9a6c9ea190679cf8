// Lavapipe's loop budget: Mesa's llvmpipe (the CI device) ends every loop of a SIMD group once
// all its loops together have iterated 65535 times (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS, a
// counter that is never reset), which would silently cut a BVH traversal, a path or a sum
// short. A loop of exactly batch.probe_iterations iterations after the work checks that the
// budget held while it ran: once it is spent, every loop runs exactly once. Elsewhere the probe
// always passes.
#ifndef TP_SHADERS_LOOP_BUDGET_GLSL
#define TP_SHADERS_LOOP_BUDGET_GLSL

#include "bindings.glsl"

bool loop_budget_held() {
    uint n = 0u;
    for (uint i = 0u; i < batch.probe_iterations; ++i) ++n;
    return n == batch.probe_iterations;
}

#endif // TP_SHADERS_LOOP_BUDGET_GLSL
