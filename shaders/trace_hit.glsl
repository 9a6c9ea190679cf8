// What a closest-hit query returns, in every trace include (trace_bvh.glsl for compute mode;
// the pipeline mode's closest-hit payload carries the same fields).
#ifndef TP_SHADERS_TRACE_HIT_GLSL
#define TP_SHADERS_TRACE_HIT_GLSL

struct TraceHit {
    float t;
    uint instance;  // FlatScene instance index
    uint primitive; // triangle index inside the instance's mesh
    vec2 bary;      // weights of vertices 1 and 2
};

#endif // TP_SHADERS_TRACE_HIT_GLSL
