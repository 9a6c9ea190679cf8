// The pipeline mode's trace include: the same two ray queries as trace_bvh.glsl, answered by
// traceRayEXT against the top-level acceleration structure
// (vulkan_rt/pipeline_mode/accel_structures.cpp), the way nvpro-samples vk_raytrace swaps
// traceray_rq.glsl for traceray_rtx.glsl. Only the ray-generation shader includes it, so it is the
// only caller of traceRayEXT: the hit and miss shaders just fill a payload, and the path loop stays
// one loop in one invocation (recursive tracing from hit shaders would need a stack per bounce and
// lose the scheduler's freedom; iOrange's rtxON part 2 and the thesis, sec. 4, make the same
// choice).
//
//   bool trace_closest(Ray ray, out TraceHit hit)  nearest hit in [0, ray.tmax]
//   bool trace_occluded(Ray ray)                   any hit in [0, ray.tmax]
//
// Vulkan's interval is closed where the BVH's is open, (0, tmax); the two differ only for a hit
// exactly at an end point. Ray origins leave surfaces by the error-bound offset (shared/offset.h;
// 4 times the bound here, render_pipeline.rgen) and shadow rays end at an offset light point
// (shared/path.h), so neither end lies on a surface.
// Geometry is opaque (VK_GEOMETRY_OPAQUE_BIT_KHR), and so are the rays, so no any-hit shader
// runs, except in a scene with alpha (FEATURE_ALPHA): there the rays leave opacity to the
// instances, and those of materials with alpha run shaders/alpha_test.rahit.
// gl_HitTEXT is the parameter of the world-space ray: the instance transform leaves t
// unchanged, as in trace_bvh.glsl.
#ifndef TP_SHADERS_TRACE_RTX_GLSL
#define TP_SHADERS_TRACE_RTX_GLSL

#extension GL_EXT_ray_tracing : require

#include "bindings.glsl"
#include "features.glsl"
#include "rt_interface.h"
#include "shared/path.h"
#include "trace_hit.glsl"

layout(set = 0, binding = BINDING_TLAS) uniform accelerationStructureEXT tlas;

// The driver keeps what the path loop holds across a traceRayEXT in memory, so the path loop
// (integrator.glsl) traces its shadow ray after drawing the scattered direction, when the
// surface point and the material are dead and need not be kept (docs/gpu.md, "Shadow ray after
// scattering"; the figures in docs/learnt.md).
const bool TRACE_SHADOW_AFTER_SCATTER = true;
// The driver's traversal re-tests a surface less precisely than the offset bound assumes
// (shared/offset.h): measured, 4 times the bound is enough (docs/stress.md).
const float TRACE_OFFSET_SLACK = 4.0f;
// Triangle lights' normals from their vertices (shared/lights.h, light_normal): here the 12
// more bytes per light read cost more than the cross product (docs/gpu.md, "Stored light
// normal").
const bool SCENE_LIGHT_NORMAL_FROM_VERTICES = true;

// The rays' opacity flag: forced opaque unless some instance needs its any-hit alpha test.
uint trace_opaque_flag() {
    return feature_on(scene_features, FEATURE_ALPHA) ? gl_RayFlagsNoneEXT : gl_RayFlagsOpaqueEXT;
}

// Both payloads are TraceHits, so that the any-hit shader, which both kinds of ray run, reads
// the ray's tag from either: a shadow ray's instance is 0 until the shadow miss shader sets it
// to TRACE_MISS.
layout(location = RT_PAYLOAD_HIT) rayPayloadEXT TraceHit rt_hit;
layout(location = RT_PAYLOAD_SHADOW) rayPayloadEXT TraceHit rt_shadow;

bool trace_closest(Ray ray, out TraceHit hit) {
    rt_hit.tag = ray.tag;
    traceRayEXT(tlas, trace_opaque_flag(), 0xFFu, 0u, 0u, RT_MISS_CLOSEST, ray.origin, 0.0f,
                ray.dir, ray.tmax, RT_PAYLOAD_HIT);
    hit = rt_hit;
    return rt_hit.instance != TRACE_MISS;
}

// The first hit found ends the search and no closest-hit shader runs; only the shadow miss
// shader writes the payload, marking the ray free.
bool trace_occluded(Ray ray) {
    rt_shadow.instance = 0u;
    rt_shadow.tag = ray.tag;
    traceRayEXT(tlas,
                gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT |
                    trace_opaque_flag(),
                0xFFu, 0u, 0u, RT_MISS_SHADOW, ray.origin, 0.0f, ray.dir, ray.tmax,
                RT_PAYLOAD_SHADOW);
    return rt_shadow.instance != TRACE_MISS;
}

#endif // TP_SHADERS_TRACE_RTX_GLSL
