// Ray-primitive tests of the compute-mode traversal and the BVH node layout they run on.
// vulkan_rt/compute_mode/bvh_builder.cpp fills the nodes; shaders/trace_bvh.glsl traverses them;
// the C++ tests call the same functions.
//
// Node layout (Aila & Laine, "Understanding the Efficiency of Ray Traversal on GPUs", HPG
// 2009, sec. 3): a binary BVH whose nodes hold the boxes of *both* children, so one 64-byte
// load gives everything needed to decide which children to visit. A child is
//   an inner node      count == 0, ref = node index
//   a leaf             count >  0, ref = first item; bottom level or one level: first
//                      BvhTriangle of `count` consecutive ones; top level: the instance index
//                      (count == 1)
//   absent             count == 0, ref == BVH_EMPTY (only in the root of a one-leaf tree)
// Two levels: the top level (over instances, world space) and every mesh's bottom level (object
// space) live in one node array; MeshInfo::bvh_root is the index of a mesh's root node. One
// level (a scene without instancing, vulkan_rt/compute_mode/bvh_builder.h): one tree whose leaves
// hold the triangles of every instance in world space.
#ifndef TP_SHARED_INTERSECT_H
#define TP_SHARED_INTERSECT_H

#include "math.h"

TP_NAMESPACE_BEGIN

// `precise` (SPIR-V NoContraction) forbids fusing a*b - c*d into an fma: the watertightness
// argument below needs every edge function computed exactly the same way in both triangles
// that share the edge. C++ compiles with -ffp-contract=off under -std=c++17 (no GNU mode).
#ifdef __cplusplus
#define TP_PRECISE
#else
#define TP_PRECISE precise
#endif

const uint BVH_EMPTY = 0xFFFFFFFFu;
const uint BVH_STACK_SIZE = 64u; // traversal stack entries; the builder checks the depth

struct BvhNode {
    vec3 lo0;    // child 0: bounding box
    uint ref0;   //          node index, first item or BVH_EMPTY
    vec3 hi0;    //
    uint count0; //          0 for an inner node, else the number of items in the leaf
    vec3 lo1;    // child 1: the same
    uint ref1;
    vec3 hi1;
    uint count1;
};

// A leaf item: the triangle's vertices, stored in leaf order so that a leaf is one contiguous
// read, and what a hit on it reports. Two levels: object-space vertices, and the instance is
// the one whose marker led the traversal there (`instance` unused, 0); one level: world-space
// vertices and their instance.
struct BvhTriangle {
    vec3 v0;
    uint primitive; // mesh-local index (FlatScene::triangles order), as Embree reports it
    vec3 v1;
    uint instance; // FlatScene instance index (one level)
    vec3 v2;
    uint pad0;
    vec3 normal; // (v1 - v0) x (v2 - v0): the plane of intersect_triangle_normal's distance
    uint pad1;
};

#ifdef __cplusplus
static_assert(sizeof(BvhNode) == 64 && offsetof(BvhNode, count1) == 60, "BvhNode layout");
static_assert(sizeof(BvhTriangle) == 64 && offsetof(BvhTriangle, normal) == 48,
              "BvhTriangle layout");
#endif

// ---- ray / box: the slab test ----------------------------------------------------------------
// Kay & Kajiya (SIGGRAPH 1986) slabs with the conservative far bound of Ize, "Robust BVH Ray
// Traversal", JCGT 2(2), 2013: every slab distance (b - o) * (1/d) carries a relative error
// below 7u (u = 2^-24: subtraction and product 0.5 ulp each, and 2.5 ulp for the division that
// made 1/d, the Vulkan bound for OpFDiv), so scaling the far distance by 1 + 2 gamma(7)
// (gamma(n) = n u / (1 - n u) ~ 8.3e-7) never rejects a box the exact test accepts. We use
// 1 + 2^-20 ~ 1 + 9.5e-7, which also absorbs the rounding of the scaling product itself.
const float AABB_FAR_SCALE = 1.0f + 1.0f / 1048576.0f;
// Replaces |d| below this by it (sign kept) so that 1/d stays finite: no inf * 0 = NaN when
// the origin lies on a slab plane. A component this small moves the ray by < 1e-20 per unit
// of t, far below float resolution for any coordinate, so no box answer changes.
const float RAY_MIN_DIRECTION = 1e-20f;

inline vec3 ray_inverse_direction(vec3 d) {
    vec3 s = vec3(d.x < 0.0f ? -1.0f : 1.0f, d.y < 0.0f ? -1.0f : 1.0f, d.z < 0.0f ? -1.0f : 1.0f);
    return s / max(abs(d), vec3(RAY_MIN_DIRECTION));
}

// Distance where the ray (org, 1/dir = inv_dir) enters box [lo, hi], clamped to >= 0; the box
// counts as hit when that entry lies before both its exit and tmax.
inline bool intersect_aabb(vec3 org, vec3 inv_dir, vec3 lo, vec3 hi, float tmax,
                           OUT(float) t_enter) {
    vec3 t0 = (lo - org) * inv_dir;
    vec3 t1 = (hi - org) * inv_dir;
    vec3 tn = min(t0, t1);
    vec3 tf = max(t0, t1);
    float t_near = max(max(tn.x, tn.y), max(tn.z, 0.0f));
    float t_far = min(min(tf.x, tf.y), tf.z) * AABB_FAR_SCALE;
    t_enter = t_near;
    return t_near <= t_far && t_near < tmax;
}

// ---- ray / triangle: watertight ------------------------------------------------------------
// Woop, Benthin & Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013. The ray is
// made the +z axis of a sheared frame (kz: the dominant axis of d; kx, ky the others, swapped
// when d_kz < 0 to keep the winding), where the vertices' 2D edge functions U, V, W decide the
// hit. A shared vertex transforms identically in both triangles of an edge and the edge
// function of the shared edge is computed as a*b - c*d in one and c*d - a*b in the other,
// which float rounding keeps exact negatives of each other, so no ray passes between them.
// The paper's double-precision recomputation when U, V or W is exactly 0 only decides which
// of the two neighbours reports such an edge hit (with this test both do); we leave it out so
// that the shaders need no 64-bit float arithmetic here.
struct WatertightRay {
    uvec3 k;    // kx, ky, kz
    vec3 shear; // Sx = d_kx / d_kz, Sy = d_ky / d_kz, Sz = 1 / d_kz
    vec3 dir;   // d, for the distance (intersect_triangle_normal)
};

inline WatertightRay watertight_ray(vec3 dir) {
    vec3 a = abs(dir);
    uint kz = a.x > a.y ? (a.x > a.z ? 0u : 2u) : (a.y > a.z ? 1u : 2u);
    uint kx = kz == 2u ? 0u : kz + 1u;
    uint ky = kx == 2u ? 0u : kx + 1u;
    if (dir[kz] < 0.0f) {
        uint swap = kx;
        kx = ky;
        ky = swap;
    }
    WatertightRay r;
    r.k = uvec3(kx, ky, kz);
    r.shear = vec3(dir[kx] / dir[kz], dir[ky] / dir[kz], 1.0f / dir[kz]);
    r.dir = dir;
    return r;
}

// Hit in (0, tmax): tuv = (t, weight of v1, weight of v2), the barycentric convention of
// surface_point() and of Embree; n = (v1 - v0) x (v2 - v0), the plane of the distance, passed
// in so that a traversal can read it rather than form it in its leaf loop, where registers are
// scarce (docs/gpu.md, "One-level BVH").
inline bool intersect_triangle_normal(vec3 org, WatertightRay r, vec3 v0, vec3 v1, vec3 v2, vec3 n,
                                      float tmax, OUT(vec3) tuv) {
    vec3 a = v0 - org;
    vec3 b = v1 - org;
    vec3 c = v2 - org;
    float ax = a[r.k.x] - r.shear.x * a[r.k.z];
    float ay = a[r.k.y] - r.shear.y * a[r.k.z];
    float bx = b[r.k.x] - r.shear.x * b[r.k.z];
    float by = b[r.k.y] - r.shear.y * b[r.k.z];
    float cx = c[r.k.x] - r.shear.x * c[r.k.z];
    float cy = c[r.k.y] - r.shear.y * c[r.k.z];
    TP_PRECISE float u = cx * by - cy * bx;
    TP_PRECISE float v = ax * cy - ay * cx;
    TP_PRECISE float w = bx * ay - by * ax;
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
    float det = u + v + w;
    if (det == 0.0f) return false; // the ray lies in the triangle's plane
    // The distance from the triangle's plane, t = (v0 - o) . n / (d . n) with n = (v1 - v0) x
    // (v2 - v0), not Woop's (u z_a + v z_b + w z_c) / det: that sums the vertices' sheared depths,
    // each rounded at the size of its coordinates, so on a triangle of size L its error is ~u L
    // whatever the distance (floor vertices at +-1e8: units, and the floor came out in front of a
    // sphere standing on it; docs/stress.md). The plane's t errs by ~u of the distance and the
    // plane's offset, and is exact for an axis-aligned plane. The edge functions above still
    // decide inside or outside, so the test stays watertight.
    float t = dot(a, n) / dot(r.dir, n);
    float inv_det = 1.0f / det;
    if (!(t > 0.0f && t < tmax)) return false;
    tuv = vec3(t, v * inv_det, w * inv_det);
    return true;
}

// The n of intersect_triangle_normal; the compute BVH builder stores it per leaf triangle.
inline vec3 triangle_plane_normal(vec3 v0, vec3 v1, vec3 v2) {
    return cross(v1 - v0, v2 - v0);
}

// The same test with the plane normal computed here.
inline bool intersect_triangle(vec3 org, WatertightRay r, vec3 v0, vec3 v1, vec3 v2, float tmax,
                               OUT(vec3) tuv) {
    return intersect_triangle_normal(org, r, v0, v1, v2, triangle_plane_normal(v0, v1, v2), tmax,
                                     tuv);
}

TP_NAMESPACE_END

#endif // TP_SHARED_INTERSECT_H
