// What a closest-hit query returns, in every trace include (trace_bvh.glsl for compute mode;
// in pipeline mode this struct is the closest-hit shader's payload, trace_rtx.glsl).
#ifndef TP_SHADERS_TRACE_HIT_GLSL
#define TP_SHADERS_TRACE_HIT_GLSL

struct TraceHit {
    float t;
    uint instance;  // FlatScene instance index; TRACE_MISS in a pipeline payload: no hit
    uint primitive; // triangle index inside the instance's mesh
    vec2 bary;      // weights of vertices 1 and 2
    // Pipeline mode: the traced ray's tag (shared/path.h, Ray::tag), which the ray-generation
    // shader puts in the payload for the any-hit alpha test (alpha_test.rahit) to read.
    uint tag;
};

// No instance: instanceCustomIndex has 24 bits, so no real instance index reaches this.
const uint TRACE_MISS = 0xFFFFFFFFu;

#endif // TP_SHADERS_TRACE_HIT_GLSL
