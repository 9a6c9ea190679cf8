// What compute mode's two traversals (trace_bvh.glsl, binary; trace_cwbvh.glsl, compressed
// 8-wide) share: the triangle array, the constants their hooks give the path loop, the cost
// view's counters and the exact test of one triangle.
#ifndef TP_SHADERS_BVH_TRIANGLES_GLSL
#define TP_SHADERS_BVH_TRIANGLES_GLSL

#include "bindings.glsl"
#include "features.glsl"
#include "shared/intersect.h"
#include "shared/path.h"
#include "shared/surface.h"
#include "trace_hit.glsl"

// The leaf items as 16-byte words, so that every load is one aligned 16-byte transaction: the
// binary layout's BvhTriangle (vulkan_rt/compute_mode/bvh_builder.h) as 4 words, a (primitive in
// w), b (with one level the instance in w), c and the plane normal; the wide layout's records
// (cwbvh.h).
layout(std430, set = 0, binding = BINDING_BVH_TRIS) readonly buffer BvhTriangleBuffer {
    vec4 bvh_triangle_words[];
};

// The traversal is inlined into the path loop, which traces its shadow ray where it has drawn
// the light sample; tracing it after scattering, as pipeline mode does, is slower here
// (docs/gpu.md, "Shadow ray after scattering").
const bool TRACE_SHADOW_AFTER_SCATTER = false;
// The watertight triangle test re-tests a surface within the offset bound (shared/offset.h).
const float TRACE_OFFSET_SLACK = 1.0f;
// Triangle lights' stored normals (shared/lights.h, light_normal).
const bool SCENE_LIGHT_NORMAL_FROM_VERTICES = false;

// The scene reads, after the hooks they take: the alpha test below reads materials.
#include "scene_access.glsl"

#ifdef TP_DEBUG_SHADER
// The traversal cost the cost view shows (debug.glsl): nodes visited and triangles tested by
// the trace calls since the view cleared them. Only in the debug variant.
#define TP_TRACE_COUNTS
uint g_trace_nodes = 0u;
uint g_trace_triangles = 0u;
#endif

// Tests the triangle (v0, v1, v2) of plane normal n with the watertight test
// (shared/intersect.h) against the ray in the space it is traversed in (origin org, wr from its
// direction): true, with its (t, u, v), where it is hit closer than tmax.
bool bvh_triangle_candidate(vec3 org, WatertightRay wr, vec3 v0, vec3 v1, vec3 v2, vec3 n,
                            float tmax, out vec3 tuv) {
#ifdef TP_TRACE_COUNTS
    ++g_trace_triangles;
#endif
    return intersect_triangle_normal(org, wr, v0, v1, v2, n, tmax, tuv);
}

// Whether a candidate's surface is there (alpha as coverage, shared/alpha.h): asked of the
// world-space ray, so that both traversals and both engines ask the same question.
bool bvh_covers(uint instance, uint primitive, vec2 bary, Ray ray) {
    return !feature_on(scene_features, FEATURE_ALPHA) ||
           scene_alpha_covers(instance, primitive, bary, ray);
}

void bvh_accept(vec3 tuv, uint instance, uint primitive, inout TraceHit hit) {
    hit.t = tuv.x;
    hit.instance = instance;
    hit.primitive = primitive;
    hit.bary = vec2(tuv.y, tuv.z);
}

// Tests BvhTriangle item i of the binary layout; a hit closer than hit.t replaces hit. With two
// levels the hit's instance is inst, the one being traversed; with one level the item's own.
bool bvh_triangle_hit(uint i, vec3 org, WatertightRay wr, bool two_level, uint inst, Ray ray,
                      inout TraceHit hit) {
    vec4 a = bvh_triangle_words[4u * i];
    vec4 b = bvh_triangle_words[4u * i + 1u];
    vec4 c = bvh_triangle_words[4u * i + 2u];
    vec3 n = bvh_triangle_words[4u * i + 3u].xyz;
    vec3 tuv;
    if (!bvh_triangle_candidate(org, wr, a.xyz, b.xyz, c.xyz, n, hit.t, tuv)) return false;
    uint instance = two_level ? inst : floatBitsToUint(b.w);
    uint primitive = floatBitsToUint(a.w);
    if (!bvh_covers(instance, primitive, vec2(tuv.y, tuv.z), ray)) return false;
    bvh_accept(tuv, instance, primitive, hit);
    return true;
}

#endif // TP_SHADERS_BVH_TRIANGLES_GLSL
