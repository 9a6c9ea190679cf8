#version 460
// Closest hits for vulkan_rt/ray_queries.h in compute mode: one ray per invocation through the
// compute mode's trace include (trace_bvh.glsl, or with TP_TRACE_WIDE trace_cwbvh.glsl; the
// render shader's bindings and BVH), the
// closest hit's distance back. On lavapipe every loop of a SIMD group stops silently once the group has
// iterated 65535 times (shaders/accumulate.glsl); a probe loop after the trace reports whether
// that budget held, so that a cut traversal is never mistaken for a leak.
#extension GL_GOOGLE_include_directive : require

#include "bindings.glsl"
#ifdef TP_TRACE_WIDE
#include "trace_cwbvh.glsl"
#else
#include "trace_bvh.glsl"
#endif

struct RayHit {
    float t;
    uint found;
    uint budget_held;
    uint pad0;
};

layout(local_size_x = 64) in;
layout(scalar, set = 0, binding = BINDING_COUNT) readonly buffer RayBuffer {
    Ray rays[];
};
layout(scalar, set = 0, binding = BINDING_COUNT + 1) writeonly buffer HitBuffer {
    RayHit hits[];
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= batch.sample_count) return;
    TraceHit h;
    RayHit o;
    o.found = trace_closest(rays[i], h) ? 1u : 0u;
    o.t = h.t;
    uint n = 0u;
    for (uint k = 0u; k < batch.probe_iterations; ++k) ++n;
    o.budget_held = n == batch.probe_iterations ? 1u : 0u;
    o.pad0 = 0u;
    hits[i] = o;
}
