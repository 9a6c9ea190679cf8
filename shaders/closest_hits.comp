#version 460
// Ray queries for vulkan_rt/renderer/gpu_ray_queries.h in compute mode: one ray per invocation
// through the compute mode's trace include (trace_bvh.glsl, or with TP_TRACE_WIDE trace_cwbvh.glsl;
// the render shader's bindings and BVH, in the shape its feature mask gives), the closest hit and
// the occlusion query's answer back. On lavapipe every loop of a SIMD group stops silently once
// the group has iterated 65535 times (shaders/render_items.glsl); a probe loop after the traces
// reports whether that budget held, so that a cut traversal is never mistaken for a miss.
#extension GL_GOOGLE_include_directive : require

#include "bindings.glsl"
#ifdef TP_TRACE_WIDE
#include "trace_cwbvh.glsl"
#else
#include "trace_bvh.glsl"
#endif

#include "ray_query_interface.h"

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
    o.instance = h.instance;
    o.primitive = h.primitive;
    o.bary = h.bary;
    o.occluded = trace_occluded(rays[i]) ? 1u : 0u;
    uint n = 0u;
    for (uint k = 0u; k < batch.probe_iterations; ++k) ++n;
    o.budget_held = n == batch.probe_iterations ? 1u : 0u;
    hits[i] = o;
}
