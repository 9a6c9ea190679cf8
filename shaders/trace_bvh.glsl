// The compute mode's trace include: ray queries answered by software traversal of the BVH of
// vulkan_rt/compute_mode/bvh_builder.cpp (node layout: shared/intersect.h). The pipeline mode
// replaces this file by one that answers the same two calls with traceRayEXT, the way nvpro-samples
// vk_raytrace swaps traceray_rq.glsl and traceray_rtx.glsl; nothing else in the shaders knows
// how rays are traced.
//
//   bool trace_closest(Ray ray, out TraceHit hit)  nearest hit in (0, ray.tmax)
//   bool trace_occluded(Ray ray)                   any hit in (0, ray.tmax)
//
// The BVH has the shape that the feature mask of the shader asks for (features.glsl,
// bvh_builder.h). Two levels (FEATURE_INSTANCING; the all-features variant): one loop and one
// stack for both levels. A popped entry is either a node index or an instance marker
// (BVH_INSTANCE_FLAG | instance) pushed when the ray met that instance's world-space box.
// Popping a marker moves the ray into the instance's object space (o' = M^-1 o, d' = M^-1 d,
// not renormalised, so t is the same parameter in both spaces and the closest distance found so
// far stays valid) and continues at the mesh's root; once the stack is back at the height it
// had then, the mesh is done and the ray returns to world space. The stack never holds more
// than depth(top) + depth(bottom) + 1 entries; the builder checks that this fits
// BVH_STACK_SIZE.
//
// One level (a scene without instancing, specialized to its mask): one tree over every
// triangle in world space, each naming its instance. The instance markers, the object-space
// copy of the ray and the return to world space all sit behind `two_level`, which the
// specialization constant makes a constant false, so the driver removes them: the loop keeps
// one ray, the stack and the closest hit. This loop sets the register peak of the whole shader
// (docs/gpu.md), so it is where a scene without instancing saves registers.
//
// Either way each visited node tests both children's boxes; leaves of triangles are
// intersected at once; of two inner children met, the far one is pushed and the near one is
// visited next straight from a register (Aila and Laine 2009), so the stack, which the driver
// keeps in local memory, is touched only for the far child.
#ifndef TP_SHADERS_TRACE_BVH_GLSL
#define TP_SHADERS_TRACE_BVH_GLSL

#include "bvh_triangles.glsl"

// The BVH nodes of vulkan_rt/compute_mode/bvh_builder.cpp, read as vec4s (BvhNode: 4 per node) so
// that every load is one aligned 16-byte transaction.
layout(std430, set = 0, binding = BINDING_BVH_NODES) readonly buffer BvhNodeBuffer {
    vec4 bvh_node_words[];
};

const uint BVH_INSTANCE_FLAG = 0x80000000u;

BvhNode bvh_load_node(uint i) {
    vec4 a = bvh_node_words[4u * i];
    vec4 b = bvh_node_words[4u * i + 1u];
    vec4 c = bvh_node_words[4u * i + 2u];
    vec4 d = bvh_node_words[4u * i + 3u];
    BvhNode n;
    n.lo0 = a.xyz;
    n.ref0 = floatBitsToUint(a.w);
    n.hi0 = b.xyz;
    n.count0 = floatBitsToUint(b.w);
    n.lo1 = c.xyz;
    n.ref1 = floatBitsToUint(c.w);
    n.hi1 = d.xyz;
    n.count1 = floatBitsToUint(d.w);
    return n;
}

bool bvh_traverse(Ray ray, bool any_hit, out TraceHit hit) {
    // False for a mask without instancing: one level, no instance state (see the top).
    bool two_level = feature_on(scene_features, FEATURE_INSTANCING);
    hit.t = ray.tmax; // the closest hit so far bounds the boxes and triangles still to test
    hit.instance = 0u;
    hit.primitive = 0u;
    hit.bary = vec2(0.0f);
    bool found = false;

    vec3 world_inv_dir = ray_inverse_direction(ray.dir);
    vec3 org = ray.origin;
    vec3 inv_dir = world_inv_dir;
    WatertightRay wr = watertight_ray(ray.dir);
    uint inst = BVH_EMPTY; // two levels: the instance whose mesh is being traversed
    uint inst_sp = 0u;     // two levels: stack height when it was entered

    uint stack[BVH_STACK_SIZE];
    uint sp = 0u;
    uint next = batch.bvh_top_root; // the entry to visit next; BVH_EMPTY: pop one
    for (;;) {
        if (next == BVH_EMPTY) {
            if (two_level && inst != BVH_EMPTY && sp == inst_sp) { // mesh done: back to world space
                inst = BVH_EMPTY;
                org = ray.origin;
                inv_dir = world_inv_dir;
            }
            if (sp == 0u) break;
            next = stack[--sp];
        }
        uint entry = next;
        next = BVH_EMPTY;
        if (two_level && (entry & BVH_INSTANCE_FLAG) != 0u) {
            inst = entry & ~BVH_INSTANCE_FLAG;
            inst_sp = sp;
            Instance I = instances[inst];
            org = instance_point_to_object(I, ray.origin);
            vec3 dir = instance_vector_to_object(I, ray.dir);
            inv_dir = ray_inverse_direction(dir);
            wr = watertight_ray(dir);
            entry = meshes[I.mesh].bvh_root;
        }
        BvhNode n = bvh_load_node(entry);
#ifdef TP_TRACE_COUNTS
        ++g_trace_nodes;
#endif
        float t0;
        float t1;
        bool hit0 = n.ref0 != BVH_EMPTY && intersect_aabb(org, inv_dir, n.lo0, n.hi0, hit.t, t0);
        bool hit1 = n.ref1 != BVH_EMPTY && intersect_aabb(org, inv_dir, n.lo1, n.hi1, hit.t, t1);
        if (!two_level || inst != BVH_EMPTY) { // leaves hold triangles: a mesh's or the one level's
            for (uint c = 0u; c < 2u; ++c) {
                bool leaf_hit = c == 0u ? hit0 && n.count0 > 0u : hit1 && n.count1 > 0u;
                if (!leaf_hit) continue;
                uint first = c == 0u ? n.ref0 : n.ref1;
                uint end = first + (c == 0u ? n.count0 : n.count1);
                for (uint i = first; i < end; ++i) {
                    if (!bvh_triangle_hit(i, org, wr, two_level, inst, ray, hit)) continue;
                    found = true;
                    if (any_hit) return true;
                }
            }
            hit0 = hit0 && n.count0 == 0u;
            hit1 = hit1 && n.count1 == 0u;
        }
        // Top-level leaves become instance markers; inner children node indices.
        uint e0 = n.count0 > 0u ? (BVH_INSTANCE_FLAG | n.ref0) : n.ref0;
        uint e1 = n.count1 > 0u ? (BVH_INSTANCE_FLAG | n.ref1) : n.ref1;
        if (hit0 && hit1) {
            bool near0 = t0 <= t1;
            stack[sp++] = near0 ? e1 : e0;
            next = near0 ? e0 : e1;
        } else if (hit0) {
            next = e0;
        } else if (hit1) {
            next = e1;
        }
    }
    return found;
}

bool trace_closest(Ray ray, out TraceHit hit) {
    return bvh_traverse(ray, false, hit);
}

bool trace_occluded(Ray ray) {
    TraceHit ignored;
    return bvh_traverse(ray, true, ignored);
}

#endif // TP_SHADERS_TRACE_BVH_GLSL
