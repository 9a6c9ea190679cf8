// The compute mode's trace include for the compressed 8-wide BVH (built by
// vulkan_rt/compute_mode/wide_bvh.h, node format: cwbvh.h): the same two calls as trace_bvh.glsl,
// which it replaces by include (render_compute.comp), answered by the traversal of Ylitie, Karras
// & Laine, "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs", HPG 2017,
// sec. 4:
//
//   bool trace_closest(Ray ray, out TraceHit hit)  nearest hit in (0, ray.tmax)
//   bool trace_occluded(Ray ray)                   any hit in (0, ray.tmax)
//
// The traversal state is a node group, a node's children still to visit as (child_base, hit
// bits 24..31 | imask), and a triangle group, (triangle_base, hit bits 0..23); the stack holds
// groups, 8 bytes each, so a node visit pushes at most one entry whatever its number of hits.
// A node's hit inner children set bit 24 + (slot ^ o), o the ray's octant code, so taking the
// highest set bit visits them in the octant order the host placed them in (roughly front to
// back); the next child's node index is child_base + the inner children in lower slots
// (bitCount of imask). Hit leaves set their triangles' bits, which are tested before the next
// node. A triangle record holds the floats of the binary layout's BvhTriangle in 48 bytes
// (cwbvh.h), tested by the same watertight test (shared/intersect.h), so a hit has the same
// distance and barycentrics; its instance and primitive come from the ID table at the end.
//
// Two levels (FEATURE_INSTANCING): the top tree's leaf items name instances. Meeting one pushes
// what remains of the current triangle and node groups, moves the ray into the instance's object
// space (as trace_bvh.glsl: t keeps its meaning) and continues at the mesh's root; when the stack
// is back at the height it had then, the ray returns to world space. With one level every
// instance branch is removed by the specialization constant.
#ifndef TP_SHADERS_TRACE_CWBVH_GLSL
#define TP_SHADERS_TRACE_CWBVH_GLSL

#include "bvh_triangles.glsl"
#include "cwbvh.h"

layout(std430, set = 0, binding = BINDING_BVH_NODES) readonly buffer CwbvhNodeBuffer {
    uvec4 cwbvh_node_words[];
};

const uint CWBVH_NODE_BITS = 0xff000000u;
// A group whose only hit is bit 31 and whose imask is empty names node child_base itself:
// the start of a traversal at a root.
const uint CWBVH_ROOT_GROUP = 0x80000000u;

// The slab distances below are q * a + b with a = 2^(e - 127) / d and b = (p - o) / d per axis
// (the paper's sec. 4 form: one multiply-add per plane). Unlike (lo - o) / d of intersect_aabb,
// their rounding error is not relative to the result: b's (p - o and the product) is below
// 1.5 u |b| and q a's below 0.5 u 255 |a| (u = 2^-24). Entry planes take b minus, exit planes b
// plus, CWBVH_PAD (|b| + 256 |a|), 16 u per unit, which covers both; what remains is relative
// to the result and is covered by AABB_FAR_SCALE as in intersect_aabb. Nothing overflows: the
// range rule (scene/flatten.h) keeps |p - o| and the box sizes within 2^38 and 1/|d| is at most
// 1e20 (ray_inverse_direction).
const float CWBVH_PAD = 1.0f / 1048576.0f;

// The ray's octant code o: bit 2 set for +x, 1 for +y, 0 for +z. The host puts in slot s the
// child lying in the octant of code s from the node's centre (vulkan_rt/compute_mode/wide_bvh.cpp);
// a ray meets first the child on the side it comes from, code o ^ 7, for which slot ^ o is 7.
uint cwbvh_octant(vec3 inv_dir) {
    return (inv_dir.x < 0.0f ? 0u : 4u) | (inv_dir.y < 0.0f ? 0u : 2u) |
           (inv_dir.z < 0.0f ? 0u : 1u);
}

vec4 cwbvh_bytes(uint w) {
    return vec4(uvec4(w, w >> 8u, w >> 16u, w >> 24u) & 0xffu);
}

// The hit mask of node (w0..w4)'s children entered before tmax: inner children at bit
// 24 + (slot ^ octant), leaf triangles at bits triangle offset .. + count - 1 (cwbvh.h).
uint cwbvh_child_hits(uvec4 w0, uvec4 w1, uvec4 w2, uvec4 w3, uvec4 w4, vec3 org, vec3 inv_dir,
                      uint octant, float tmax) {
    vec3 scale = uintBitsToFloat((uvec3(w0.w, w0.w >> 8u, w0.w >> 16u) & 0xffu) << 23u);
    vec3 a = scale * inv_dir;
    vec3 b = (uintBitsToFloat(w0.xyz) - org) * inv_dir;
    vec3 pad = (abs(b) + 256.0f * abs(a)) * CWBVH_PAD;
    vec3 b_in = b - pad;
    vec3 b_out = b + pad;
    bvec3 pos = greaterThanEqual(inv_dir, vec3(0.0f));
    uint hits = 0u;
    for (uint half_ = 0u; half_ < 2u; ++half_) {
        bool h = half_ == 0u;
        uint lo_x = h ? w2.x : w2.y, lo_y = h ? w2.z : w2.w, lo_z = h ? w3.x : w3.y;
        uint hi_x = h ? w3.z : w3.w, hi_y = h ? w4.x : w4.y, hi_z = h ? w4.z : w4.w;
        // A positive direction enters a box at its low plane, a negative one at its high plane.
        vec4 t_in_x = cwbvh_bytes(pos.x ? lo_x : hi_x) * a.x + b_in.x;
        vec4 t_in_y = cwbvh_bytes(pos.y ? lo_y : hi_y) * a.y + b_in.y;
        vec4 t_in_z = cwbvh_bytes(pos.z ? lo_z : hi_z) * a.z + b_in.z;
        vec4 t_out_x = cwbvh_bytes(pos.x ? hi_x : lo_x) * a.x + b_out.x;
        vec4 t_out_y = cwbvh_bytes(pos.y ? hi_y : lo_y) * a.y + b_out.y;
        vec4 t_out_z = cwbvh_bytes(pos.z ? hi_z : lo_z) * a.z + b_out.z;
        vec4 t_in = max(max(t_in_x, t_in_y), max(t_in_z, vec4(0.0f)));
        vec4 t_out = min(min(t_out_x, t_out_y), t_out_z) * AABB_FAR_SCALE;
        uint meta4 = h ? w1.z : w1.w;
        for (uint j = 0u; j < 4u; ++j) {
            uint m = (meta4 >> (8u * j)) & 0xffu;
            bool inner = (m & 0x18u) == 0x18u; // offsets 24..31 name inner slots
            uint bit = inner ? ((m & 0x1fu) ^ octant) : (m & 0x1fu);
            if (t_in[j] <= t_out[j] && t_in[j] < tmax) hits |= (m >> 5u) << bit;
        }
    }
    return hits;
}

// The primitive, and with one level the instance, of the closest hit's record from the ID
// table (cwbvh.h): read once per query, not in the leaf loop.
void cwbvh_hit_ids(bool two_level, inout TraceHit hit) {
    uvec2 head = floatBitsToUint(bvh_triangle_words[0].xy); // the table's word, b
    bool pairs = head.y == CWBVH_ID_PAIRS;
    uint u = pairs ? 2u * hit.primitive : hit.primitive;
    vec4 w = bvh_triangle_words[head.x + (u >> 2u)];
    uint id = floatBitsToUint(w[u & 3u]);
    if (pairs) {
        hit.primitive = id;
        hit.instance = floatBitsToUint(w[(u & 3u) + 1u]);
    } else {
        hit.primitive = id >> head.y;
        if (!two_level) hit.instance = id & ((1u << head.y) - 1u);
    }
}

// Tests triangle record i (cwbvh.h). The hit names record i as its primitive and inst as its
// instance until cwbvh_hit_ids replaces them with what the record stands for; the alpha test,
// where the scene has alpha, resolves them for the candidate at once.
bool cwbvh_triangle_hit(uint i, vec3 org, WatertightRay wr, bool two_level, uint inst, Ray ray,
                        inout TraceHit hit) {
    uint w = CWBVH_TRIANGLE_WORDS * i + 1u;
    vec4 a = bvh_triangle_words[w];
    vec4 b = bvh_triangle_words[w + 1u];
    vec4 c = bvh_triangle_words[w + 2u];
    vec3 tuv;
    if (!bvh_triangle_candidate(org, wr, a.xyz, b.xyz, c.xyz, vec3(a.w, b.w, c.w), hit.t, tuv))
        return false;
    if (feature_on(scene_features, FEATURE_ALPHA)) {
        TraceHit ids;
        ids.t = tuv.x;
        ids.instance = inst;
        ids.primitive = i;
        ids.bary = vec2(tuv.y, tuv.z);
        cwbvh_hit_ids(two_level, ids);
        if (!scene_alpha_covers(ids.instance, ids.primitive, ids.bary, ray)) return false;
    }
    bvh_accept(tuv, inst, i, hit);
    return true;
}

bool cwbvh_traverse(Ray ray, bool any_hit, out TraceHit hit) {
    // False for a mask without instancing: one level, no instance state.
    bool two_level = feature_on(scene_features, FEATURE_INSTANCING);
    hit.t = ray.tmax;
    hit.instance = 0u;
    hit.primitive = 0u;
    hit.bary = vec2(0.0f);
    bool found = false;

    vec3 world_inv_dir = ray_inverse_direction(ray.dir);
    uint world_octant = cwbvh_octant(world_inv_dir);
    vec3 org = ray.origin;
    vec3 inv_dir = world_inv_dir;
    uint octant = world_octant;
    WatertightRay wr = watertight_ray(ray.dir);
    uint inst = BVH_EMPTY; // two levels: the instance whose mesh is being traversed
    uint inst_sp = 0u;     // two levels: stack height when it was entered

    uvec2 stack[CWBVH_STACK_SIZE];
    uint sp = 0u;
    uvec2 group = uvec2(batch.bvh_top_root, CWBVH_ROOT_GROUP);
    for (;;) {
        uvec2 tris;
        if ((group.y & CWBVH_NODE_BITS) != 0u) {
            uint bit = uint(findMSB(group.y));
            group.y &= ~(1u << bit);
            uint slot = (bit - 24u) ^ octant;
            uint node = group.x + uint(bitCount(group.y & ((1u << slot) - 1u) & 0xffu));
            if ((group.y & CWBVH_NODE_BITS) != 0u) stack[sp++] = group;
            uvec4 w0 = cwbvh_node_words[CWBVH_NODE_WORDS * node];
            uvec4 w1 = cwbvh_node_words[CWBVH_NODE_WORDS * node + 1u];
            uvec4 w2 = cwbvh_node_words[CWBVH_NODE_WORDS * node + 2u];
            uvec4 w3 = cwbvh_node_words[CWBVH_NODE_WORDS * node + 3u];
            uvec4 w4 = cwbvh_node_words[CWBVH_NODE_WORDS * node + 4u];
#ifdef TP_TRACE_COUNTS
            ++g_trace_nodes;
#endif
            uint hits = cwbvh_child_hits(w0, w1, w2, w3, w4, org, inv_dir, octant, hit.t);
            group = uvec2(w1.x, (hits & CWBVH_NODE_BITS) | (w0.w >> 24u));
            tris = uvec2(w1.y, hits & ~CWBVH_NODE_BITS);
        } else { // a triangle group from the stack (two levels: instances still to enter)
            tris = group;
            group = uvec2(0u);
        }
        while (tris.y != 0u) {
            uint bit = uint(findMSB(tris.y));
            tris.y &= ~(1u << bit);
            uint i = tris.x + bit;
            if (two_level && inst == BVH_EMPTY) { // a top-level item: enter its instance
                if (tris.y != 0u) stack[sp++] = tris;
                if ((group.y & CWBVH_NODE_BITS) != 0u) stack[sp++] = group;
                inst = floatBitsToUint(bvh_triangle_words[CWBVH_TRIANGLE_WORDS * i + 1u].x);
                inst_sp = sp;
                Instance I = instances[inst];
                org = instance_point_to_object(I, ray.origin);
                vec3 dir = instance_vector_to_object(I, ray.dir);
                inv_dir = ray_inverse_direction(dir);
                octant = cwbvh_octant(inv_dir);
                wr = watertight_ray(dir);
                group = uvec2(meshes[I.mesh].bvh_root, CWBVH_ROOT_GROUP);
                break;
            }
            if (!cwbvh_triangle_hit(i, org, wr, two_level, inst, ray, hit)) continue;
            found = true;
            if (any_hit) return true;
        }
        if ((group.y & CWBVH_NODE_BITS) == 0u) {
            if (two_level && inst != BVH_EMPTY && sp == inst_sp) { // mesh done: back to world
                inst = BVH_EMPTY;
                org = ray.origin;
                inv_dir = world_inv_dir;
                octant = world_octant;
            }
            if (sp == 0u) break;
            group = stack[--sp];
        }
    }
    if (found) cwbvh_hit_ids(two_level, hit);
    return found;
}

bool trace_closest(Ray ray, out TraceHit hit) {
    return cwbvh_traverse(ray, false, hit);
}

bool trace_occluded(Ray ray) {
    TraceHit ignored;
    return cwbvh_traverse(ray, true, ignored);
}

#endif // TP_SHADERS_TRACE_CWBVH_GLSL
