#version 460
// Traces one ray per invocation through the compute mode's trace include (the render shader's
// bindings and BVH; with TP_TRACE_WIDE the compressed 8-wide BVH's), for comparison with Embree:
// the closest hit and the occlusion answer.
// batch.sample_count holds the number of rays.
#extension GL_GOOGLE_include_directive : require

#include "bindings.glsl"
#ifdef TP_TRACE_WIDE
#include "trace_cwbvh.glsl"
#else
#include "trace_bvh.glsl"
#endif

struct TraceResult {
    float t;
    uint instance;
    uint primitive;
    uint found;
    vec2 bary;
    uint occluded;
    uint pad0;
};

layout(local_size_x = 64) in;
layout(scalar, set = 0, binding = BINDING_COUNT) readonly buffer RayBuffer { Ray rays[]; };
layout(scalar, set = 0, binding = BINDING_COUNT + 1) writeonly buffer ResultBuffer {
    TraceResult results[];
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= batch.sample_count) return;
    Ray r = rays[i];
    TraceHit h;
    TraceResult o;
    o.found = trace_closest(r, h) ? 1u : 0u;
    o.t = h.t;
    o.instance = h.instance;
    o.primitive = h.primitive;
    o.bary = h.bary;
    o.occluded = trace_occluded(r) ? 1u : 0u;
    o.pad0 = 0u;
    results[i] = o;
}
